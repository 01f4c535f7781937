#include "crowd_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "frame.h"
#include "mobb/core/angle.h"

namespace mobb::viewer {

namespace {

// Seconds either side of the cursor a crowd shows at first: a slab of the run, not all of it.
constexpr double kCrowdWindow = 5.0;

const glm::vec3 kAccepted{0.25f, 0.80f, 0.30f}, kRejected{0.90f, 0.20f, 0.20f}, kCommitted{0.95f, 0.85f, 0.20f};

/// Drops every clip after the agents (candidates, the opened query's other clip).
void drop_extra(State& s) {
    const std::size_t n = std::size_t(s.crowd->agents);
    s.clips.resize(n);
    s.places.resize(n);
    s.fixed_paths.resize(n);
    s.colors.resize(n);
    s.crowd->candidate_clips.clear();
    s.crowd->accepted.clear();
    s.crowd->opened_candidate = s.crowd->opened_query = -1;
    s.scene.query_a = s.scene.query_b = -1;
    s.scene.step = -1;
}

int add_clip(State& s, const std::string& name, const Path& path, const Placement& place, const glm::vec3& color) {
    LoadedClip c;
    c.name = name;
    c.tree = std::make_unique<Tree>(Tree::build(path, s.scene.tree));
    s.clips.push_back(std::move(c));
    s.places.push_back(place);
    s.fixed_paths.push_back(path);
    s.colors.push_back(color);
    return int(s.clips.size()) - 1;
}

/// Drops the clip an earlier opened query added after the candidates.
void drop_opened(State& s) {
    const CrowdView& v = *s.crowd;
    std::size_t keep = std::size_t(v.agents);
    for (int c : v.candidate_clips) keep = std::max(keep, std::size_t(c + 1));
    s.clips.resize(keep);
    s.places.resize(keep);
    s.fixed_paths.resize(keep);
    s.colors.resize(keep);
}

/// Agent a's stack from the window's frames: its disks while in the run. An agent that left before the
/// window has none there: one disk of radius 0 at its last goal (where it left), not drawn.
Path agent_path(const crowd::SampleWindow& w, std::size_t a, const crowd::AgentTrack& track, bool& shown, double& t0) {
    Path path;
    path.dt = w.dt;
    path.samples.reserve(std::size_t(w.last - w.first));
    t0 = double(w.first) * w.dt;
    for (std::int64_t f = w.first; f < w.last; ++f) {
        const std::array<double, 4>* d = crowd::window_disk(w, a, f);
        if (!d) break;
        if (path.samples.empty()) t0 = (*d)[0];
        path.samples.push_back({(*d)[1], (*d)[2], (*d)[3]});
    }
    shown = !path.samples.empty();
    if (!shown) {
        const std::array<double, 2> at = track.goals.empty() ? std::array<double, 2>{0, 0} : track.goals.back();
        path.samples.push_back({at[0], at[1], 0.0});
    }
    return path;
}

/// The agents' stacks (the state's first clips) from the window's frames.
void build_agents(State& s) {
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record();
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        bool shown = true;
        double t0 = 0;
        Path path = agent_path(v.window, a, r.tracks[a], shown, t0);
        LoadedClip& c = s.clips[a];
        c.tree = std::make_unique<Tree>(Tree::build(path, s.scene.tree));
        c.hidden = !shown;
        s.places[a] = {0, 0, 0, t0};  // frame k of the record starts at t = k * dt
        s.fixed_paths[a] = std::move(path);
    }
    ++s.revision;
}

/// Reads frames first .. last - 1 into the view: the window, its contacts, the timeline's marks.
void read_window(CrowdView& v, std::int64_t first, std::int64_t last) {
    v.window = v.reader->samples(first, last);  // the poser reads it where it stands
    mark_contacts(v);
}

}  // namespace

void mark_contacts(CrowdView& v) {
    v.contacts = crowd::frame_contacts(v.window, v.record());
    // The window's frames marked anew (a frame read again counts once).
    auto it = v.contact_marks.lower_bound(v.window.first);
    while (it != v.contact_marks.end() && it->first < v.window.last) it = v.contact_marks.erase(it);
    for (const crowd::Contact& c : v.contacts)
        ++v.contact_marks.try_emplace(c.frame, TimelineMark{TimelineMark::Contact, c.frame, c.a, -1, 0})
              .first->second.count;
    v.marks = timeline_marks(v);
}

namespace {

/// Frame k's first and last covered by seconds t0 .. t1, clamped to the run.
std::pair<std::int64_t, std::int64_t> frames_of(double t0, double t1, double dt, std::int64_t frames) {
    const auto lo = std::int64_t(std::floor(t0 / dt)), hi = std::int64_t(std::ceil(t1 / dt)) + 1;
    return {std::clamp<std::int64_t>(lo, 0, frames), std::clamp<std::int64_t>(hi, 0, frames)};
}

}  // namespace

std::pair<std::int64_t, std::int64_t> crowd_frames_wanted(const State& s) {
    const CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record();
    const std::size_t agents = std::max<std::size_t>(1, r.tracks.size());
    if (std::size_t(r.frames) <= v.window_disks / agents) return {0, r.frames};
    const double w = s.scene.window > 0 ? s.scene.window + kCrowdReadAhead : double(r.frames) * r.dt;
    auto [lo, hi] = frames_of(s.scene.cursor - w, s.scene.cursor + w, r.dt, r.frames);
    // At most window_disks disks, about the cursor.
    const auto most = std::max<std::int64_t>(1, std::int64_t(v.window_disks / agents));
    if (hi - lo > most) {
        const auto at = std::clamp<std::int64_t>(std::int64_t(std::floor(s.scene.cursor / r.dt)), 0, r.frames - 1);
        lo = std::clamp<std::int64_t>(at - most / 2, 0, r.frames - most);
        hi = lo + most;
    }
    return {lo, hi};
}

bool sync_crowd(State& s) {
    if (!s.crowd) return false;
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record();
    const auto [lo, hi] = crowd_frames_wanted(s);
    // The frames drawn (the window around the cursor), as many of them as can be had at once.
    auto [need_lo, need_hi] =
        s.scene.window > 0 ? frames_of(s.scene.cursor - s.scene.window, s.scene.cursor + s.scene.window, r.dt, r.frames)
                           : std::pair<std::int64_t, std::int64_t>{0, r.frames};
    need_lo = std::max(need_lo, lo), need_hi = std::min(need_hi, hi);
    if (v.window.first <= need_lo && need_hi <= v.window.last && v.window.last > v.window.first) return false;
    if (v.unread == std::pair{lo, hi}) return false;  // it failed: once is enough
    try {
        read_window(v, lo, hi);
    } catch (const std::runtime_error&) {
        v.unread = {lo, hi};
        throw;
    }
    build_agents(s);
    return true;
}

State load_crowd_state(const std::string& record_file, float aspect, double cursor, double window,
                       std::size_t window_disks) {
    auto view = std::make_shared<CrowdView>();
    view->reader = crowd::open_record(record_file);
    view->window_disks = window_disks;
    const crowd::Record& r = view->record();
    try {
        view->graph = std::make_shared<crowd::MotionGraph>(crowd::load_graph(r.graph));
        view->poses = std::make_shared<PoseSources>(view->graph);
    } catch (const std::exception& e) {
        view->graph_error = e.what();
    }
    if (view->graph) {
        try {  // a graph that reads but lacks the record's clips is not the record's graph
            view->reader->check_graph_clips(view->graph->clips.size());
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(record_file + ": " + e.what());
        }
    }
    State s;
    s.scene.query_a = s.scene.query_b = -1;
    s.scene.layers.skeletons = true;
    s.scene.layers.trace = false;
    s.scene.skeleton_scale = 1.0;  // life-size at 1 m per s: a crowd is seen from farther than a pair
    // The whole run at most about as tall as the world is wide, on a round scale (a metre per second at most).
    const double run = double(r.frames) * r.dt, fit = std::max(r.world.width(), r.world.height()) / std::max(run, 1e-9);
    s.scene.time_scale = 0.05;
    for (double scale : {1.0, 0.5, 0.25, 0.2, 0.1})
        if (scale <= fit * 1.25) {
            s.scene.time_scale = scale;
            break;
        }
    s.scene.window = window >= 0 ? window : kCrowdWindow;
    s.scene.cursor = cursor >= 0 ? cursor : 0.5 * run;
    s.scene.width = 960;
    s.scene.height = 540;
    view->agents = int(r.tracks.size());
    view->fallbacks = view->reader->fallbacks();
    s.crowd = view;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        s.clips.emplace_back().name = "agent " + std::to_string(a);
        s.places.emplace_back();
        s.fixed_paths.emplace_back();
        s.colors.push_back(render::clip_color(int(a)));
    }
    try {
        sync_crowd(s);
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        throw std::runtime_error(m.rfind(record_file, 0) == 0 ? m : record_file + ": " + m);
    }
    frame_all(s, aspect);
    return s;
}

const std::vector<crowd::ChoiceSummary>& agent_choices(CrowdView& v, int agent) {
    if (agent != v.listed_agent || v.window.first != v.listed_first || v.window.last != v.listed_last) {
        const auto [lo, hi] = v.whole() ? std::pair<std::size_t, std::size_t>{0, v.reader->choice_count()}
                                        : v.reader->choice_rows(v.window.first, v.window.last);
        v.listed = v.reader->summaries(lo, hi, agent);
        std::stable_sort(v.listed.begin(), v.listed.end(),
                         [](const auto& a, const auto& b) { return a.point.frame < b.point.frame; });
        v.listed_agent = agent, v.listed_first = v.window.first, v.listed_last = v.window.last;
    }
    return v.listed;
}

const crowd::PlacedClip* committed_at(const CrowdView& v, const crowd::ChoicePoint& c) {
    if (c.agent < 0 || std::size_t(c.agent) >= v.record().tracks.size()) return nullptr;
    for (const crowd::PlacedClip& p : v.record().tracks[std::size_t(c.agent)].clips)
        if (p.start == c.frame && p.clip == c.taken) return &p;
    return nullptr;
}

std::optional<crowd::FramedClip> query_clip(const CrowdView& v, const crowd::CandidateQuery& q) {
    const auto it = q.choice >= 0 ? v.named.find(std::size_t(q.choice)) : v.named.end();
    return crowd::query_clip(v.record(), q, it == v.named.end() ? nullptr : &it->second);
}

render::Bounds crowd_extent(const CrowdView& v) {
    render::Bounds b;
    if (v.whole()) return b;  // the agents' stacks span the run
    const crowd::Record& r = v.record();
    b.add({r.world.x0, r.world.y0, 0.0});
    b.add({r.world.x1, r.world.y1, double(r.frames) * r.dt});
    return b;
}

void select_choice(State& s, int agent, int choice) {
    CrowdView& v = *s.crowd;
    drop_extra(s);
    if (agent >= 0 && agent < v.agents) v.agent = agent;
    v.choice = choice >= 0 && std::size_t(choice) < v.reader->choice_count() ? choice : -1;
    v.named.clear();
    for (int a = 0; a < v.agents; ++a)
        s.colors[std::size_t(a)] = v.choice < 0 || a == v.agent ? render::clip_color(a) : glm::vec3(0.55f);
    if (v.choice >= 0) {
        v.selected = v.reader->choice(std::size_t(v.choice));
        const crowd::ChoicePoint& c = v.selected;
        // The choice points whose escape clips its queries met (the clips taken are the tracks').
        for (const crowd::Candidate& cand : c.candidates)
            for (const crowd::CandidateQuery& q : cand.against)
                if (q.agent >= 0 && q.piece > 0 && q.choice >= 0 && std::size_t(q.choice) < v.reader->choice_count() &&
                    !v.named.count(std::size_t(q.choice)))
                    v.named.emplace(std::size_t(q.choice), v.reader->choice(std::size_t(q.choice)));
        v.agent = c.agent;
        s.colors.assign(std::size_t(v.agents), glm::vec3(0.55f));
        s.colors[std::size_t(v.agent)] = render::clip_color(v.agent);
        const crowd::PlacedClip* at = committed_at(v, c);
        if (v.graph && at) {
            for (const crowd::Candidate& cand : c.candidates) {
                const bool ok = !cand.leaves_world && !cand.meets_solid && cand.hits == 0 && !cand.crowded;
                const glm::vec3 color = cand.clip == c.taken ? kCommitted : ok ? kAccepted : kRejected;
                v.accepted.push_back(ok);
                if (cand.clip < 0 || std::size_t(cand.clip) >= v.graph->clips.size()) {
                    v.candidate_clips.push_back(-1);  // kept aligned with the candidates
                    continue;
                }
                v.candidate_clips.push_back(add_clip(s, "candidate clip " + std::to_string(cand.clip),
                                                     v.graph->clips[std::size_t(cand.clip)].path, at->place, color));
            }
        }
    }
    ++s.revision;
}

bool open_candidate_query(State& s, int k, int j, std::string* message) {
    CrowdView& v = *s.crowd;
    auto fail = [&](const std::string& m) {
        if (message) *message = m;
        return false;
    };
    if (v.choice < 0) return fail("no choice point selected");
    if (!v.graph) return fail("the record's graph cannot be read: " + v.graph_error);
    const crowd::ChoicePoint& c = v.selected;
    if (k < 0 || std::size_t(k) >= c.candidates.size() || std::size_t(k) >= v.candidate_clips.size())
        return fail("no candidate " + std::to_string(k));
    const crowd::Candidate& cand = c.candidates[std::size_t(k)];
    if (j < 0 || std::size_t(j) >= cand.against.size())
        return fail("candidate clip " + std::to_string(cand.clip) + " has no query " + std::to_string(j));
    const int a = v.candidate_clips[std::size_t(k)];
    if (a < 0) return fail("candidate clip " + std::to_string(cand.clip) + " is not in the graph");
    const crowd::CandidateQuery& q = cand.against[std::size_t(j)];
    // The record places the candidate clip; the escape clips of the routes it tried are not kept.
    if (q.mine != 0)
        return fail("query " + std::to_string(j) + " was asked by the candidate's " +
                    (q.mine > 0 ? "escape clip " + std::to_string(q.mine) : std::string("held ground")) +
                    ": not a clip to trace");
    std::optional<crowd::FramedClip> against;
    try {
        against = query_clip(v, q);
    } catch (const std::out_of_range&) {
        return fail("query " + std::to_string(j) + " names no clip of the record");
    }
    if (!against)
        return fail("query " + std::to_string(j) + " was against " +
                    (q.agent < 0 ? "a wall or an obstacle" : "agent " + std::to_string(q.agent) + "'s held ground") +
                    ": not a clip to trace");
    const crowd::FramedClip& other = *against;
    if (other.clip < 0 || std::size_t(other.clip) >= v.graph->clips.size())
        return fail("agent " + std::to_string(q.agent) + "'s clip " + std::to_string(other.clip) +
                    " is not in the graph");
    drop_opened(s);
    const int b = add_clip(s, "agent " + std::to_string(q.agent) + " clip " + std::to_string(other.clip),
                           v.graph->clips[std::size_t(other.clip)].path, other.place, render::clip_color(q.agent));
    s.scene.query_a = a;
    s.scene.query_b = b;
    run_query(s);
    s.scene.step = 0;
    s.scene.layers.trace = true;
    v.opened_candidate = k;
    v.opened_query = j;
    if (message)
        *message = "candidate clip " + std::to_string(cand.clip) + " vs agent " + std::to_string(q.agent) + " clip " +
                   std::to_string(other.clip) + (s.answer ? ": collide" : ": clear") +
                   (s.answer == q.hit ? " (as recorded)" : " (the record says otherwise)");
    return true;
}

namespace {

/// A record frame is a graph sample only when both share dt (else the poses would drift off the disks).
bool same_rate(const CrowdView& v) { return v.graph && std::abs(v.record().dt - v.graph->dt()) < 1e-9; }

}  // namespace

std::string skeleton_problem(const CrowdView& v) {
    if (!v.graph) return "no graph: " + v.graph_error;
    if (!same_rate(v)) return "the record's dt differs from its graph's (" + v.record().graph + ")";
    if (!v.pose_error.empty()) return v.pose_error;
    return v.poses ? v.poses->error() : std::string();
}

std::vector<render::PosedSkeleton> agent_skeletons(CrowdView& v, double t, const std::vector<glm::vec3>& colors,
                                                   std::vector<render::Prism>* planted) {
    if (!v.graph || !v.poses || !same_rate(v)) return {};
    if (!v.poser && v.pose_error.empty()) {
        try {
            v.poser = std::make_shared<crowd::CrowdPoser>(v.record(), v.poses);
            v.poser->use_samples(&v.window);
            v.bones = drawn_bones(v.poser->rig());
        } catch (const std::exception& e) {
            v.pose_error = e.what();
        }
    }
    return v.poser ? crowd_skeletons(*v.poser, v.bones, t, colors, planted) : std::vector<render::PosedSkeleton>{};
}

void update_crowd_playback(State& s, double seconds) {
    if (!s.crowd || !s.crowd->playing) return;
    const double end = double(s.crowd->record().frames) * s.crowd->record().dt;
    s.scene.cursor += seconds * double(s.crowd->rate);
    if (end > 0 && s.scene.cursor > end) s.scene.cursor = std::fmod(s.scene.cursor, end);
}

namespace {

std::vector<std::array<double, 2>> circle(double x, double y, double r, int sides) {
    std::vector<std::array<double, 2>> out;
    for (int k = 0; k < sides; ++k) {
        const double a = 2 * kPi * k / sides;
        out.push_back({x + r * std::cos(a), y + r * std::sin(a)});
    }
    return out;
}

}  // namespace

std::vector<render::Prism> crowd_prisms(const CrowdView& v, double t) {
    const crowd::Record& r = v.record();
    const double end = double(r.frames) * r.dt;
    std::vector<render::Prism> out;
    const crowd::World& w = r.world;
    if (w.walls)
        out.push_back({crowd::Polygon::rectangle(w.x0, w.y0, w.x1, w.y1).vertices, 0, end, glm::vec3(0.35f), 0, false});
    for (const crowd::Polygon& p : w.obstacles) out.push_back({p.vertices, 0, end, glm::vec3(0.30f), 0.35f, false});
    // Goals in the agent's colour while it is in the run: a sequence's goals small, its last one larger.
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const crowd::AgentTrack& track = r.tracks[a];
        const double until = double(track.left_frame.value_or(r.frames)) * r.dt;
        for (std::size_t k = 0; k < track.goals.size(); ++k) {
            const double size = k + 1 == track.goals.size() ? 0.15 : 0.08;
            out.push_back({circle(track.goals[k][0], track.goals[k][1], size, 4), 0, until, render::clip_color(int(a)),
                           0.6f, false});
        }
    }
    const auto frame = std::int64_t(std::floor(t / r.dt));
    auto it = std::lower_bound(v.contacts.begin(), v.contacts.end(), frame,
                               [](const crowd::Contact& c, std::int64_t f) { return c.frame < f; });
    for (; it != v.contacts.end() && it->frame == frame; ++it)
        for (int a : {it->a, it->b})
            if (const auto* d = crowd::window_disk(v.window, std::size_t(a), frame))
                out.push_back(
                    {circle((*d)[1], (*d)[2], (*d)[3] + 0.04, 24), t, t, glm::vec3(0.95f, 0.1f, 0.1f), 0, true});
    return out;
}

std::vector<TimelineMark> timeline_marks(const CrowdView& v) {
    std::vector<TimelineMark> out;
    for (const crowd::ChoiceMark& c : v.fallbacks)
        out.push_back({TimelineMark::Fallback, c.frame, c.agent, int(c.row), 1});
    for (const auto& [frame, mark] : v.contact_marks) out.push_back(mark);
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.frame < b.frame; });
    return out;
}

const TimelineMark* nearest_mark(const std::vector<TimelineMark>& marks, std::int64_t frame, std::int64_t reach) {
    const TimelineMark* best = nullptr;
    for (const TimelineMark& m : marks) {
        const std::int64_t d = m.frame > frame ? m.frame - frame : frame - m.frame;
        if (d <= reach && (!best || d < (best->frame > frame ? best->frame - frame : frame - best->frame))) best = &m;
    }
    return best;
}

void jump_to(State& s, const TimelineMark& m) {
    CrowdView& v = *s.crowd;
    if (m.kind == TimelineMark::Fallback)
        select_choice(s, m.agent, m.choice);
    else
        select_choice(s, m.agent, -1);
    // Inside the frame, so the contacts of that frame show at the cursor.
    s.scene.cursor = (double(m.frame) + 0.5) * v.record().dt;
}

}  // namespace mobb::viewer
