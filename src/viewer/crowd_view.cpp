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

}  // namespace

State load_crowd_state(const std::string& record_file, float aspect) {
    auto view = std::make_shared<CrowdView>();
    view->record = crowd::load_record(record_file);
    const crowd::Record& r = view->record;
    try {
        view->graph = std::make_shared<crowd::MotionGraph>(crowd::load_graph(r.graph));
        view->poses = std::make_shared<PoseSources>(view->graph);
    } catch (const std::exception& e) {
        view->graph_error = e.what();
    }
    if (view->graph) {
        try {  // a graph that reads but lacks the record's clips is not the record's graph
            crowd::check_graph_clips(r, view->graph->clips.size());
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
    s.scene.window = kCrowdWindow;
    s.scene.width = 960;
    s.scene.height = 540;
    view->agents = int(r.tracks.size());
    view->contacts = crowd::frame_contacts(r);
    view->marks = timeline_marks(*view);
    s.crowd = view;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        Path path;
        path.dt = r.dt;
        for (const auto& q : r.tracks[a].samples) path.samples.push_back({q[1], q[2], q[3]});
        if (path.samples.empty())
            throw std::runtime_error(record_file + ": agent " + std::to_string(a) + " has no samples");
        // Frame k of the record starts at t = k * dt: the path starts at the record's first sample time.
        add_clip(s, "agent " + std::to_string(a), path, {0, 0, 0, r.tracks[a].samples.front()[0]},
                 render::clip_color(int(a)));
    }
    ++s.revision;
    frame_all(s, aspect);
    return s;
}

std::vector<int> agent_choices(const CrowdView& v, int agent) {
    std::vector<int> out;
    for (std::size_t k = 0; k < v.record.choices.size(); ++k)
        if (v.record.choices[k].agent == agent) out.push_back(int(k));
    std::stable_sort(out.begin(), out.end(), [&](int a, int b) {
        return v.record.choices[std::size_t(a)].frame < v.record.choices[std::size_t(b)].frame;
    });
    return out;
}

const crowd::PlacedClip* committed_at(const CrowdView& v, const crowd::ChoicePoint& c) {
    if (c.agent < 0 || std::size_t(c.agent) >= v.record.tracks.size()) return nullptr;
    for (const crowd::PlacedClip& p : v.record.tracks[std::size_t(c.agent)].clips)
        if (p.start == c.frame && p.clip == c.taken) return &p;
    return nullptr;
}

void select_choice(State& s, int agent, int choice) {
    CrowdView& v = *s.crowd;
    drop_extra(s);
    if (agent >= 0 && agent < v.agents) v.agent = agent;
    v.choice = choice >= 0 && std::size_t(choice) < v.record.choices.size() ? choice : -1;
    for (int a = 0; a < v.agents; ++a)
        s.colors[std::size_t(a)] = v.choice < 0 || a == v.agent ? render::clip_color(a) : glm::vec3(0.55f);
    if (v.choice >= 0) {
        const crowd::ChoicePoint& c = v.record.choices[std::size_t(v.choice)];
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
    const crowd::ChoicePoint& c = v.record.choices[std::size_t(v.choice)];
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
        against = crowd::query_clip(v.record, q);
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
bool same_rate(const CrowdView& v) { return v.graph && std::abs(v.record.dt - v.graph->dt()) < 1e-9; }

}  // namespace

std::string skeleton_problem(const CrowdView& v) {
    if (!v.graph) return "no graph: " + v.graph_error;
    if (!same_rate(v)) return "the record's dt differs from its graph's (" + v.record.graph + ")";
    if (!v.pose_error.empty()) return v.pose_error;
    return v.poses ? v.poses->error() : std::string();
}

std::vector<render::PosedSkeleton> agent_skeletons(CrowdView& v, double t, const std::vector<glm::vec3>& colors) {
    if (!v.graph || !v.poses || !same_rate(v)) return {};
    if (!v.poser && v.pose_error.empty()) {
        try {
            v.poser = std::make_shared<crowd::CrowdPoser>(v.record, v.poses);
            v.bones = drawn_bones(v.poser->rig());
        } catch (const std::exception& e) {
            v.pose_error = e.what();
        }
    }
    return v.poser ? crowd_skeletons(*v.poser, v.bones, t, colors) : std::vector<render::PosedSkeleton>{};
}

void update_crowd_playback(State& s, double seconds) {
    if (!s.crowd || !s.crowd->playing) return;
    const double end = double(s.crowd->record.frames) * s.crowd->record.dt;
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
    const crowd::Record& r = v.record;
    const double end = double(r.frames) * r.dt;
    std::vector<render::Prism> out;
    const crowd::World& w = r.world;
    if (w.walls)
        out.push_back({crowd::Polygon::rectangle(w.x0, w.y0, w.x1, w.y1).vertices, 0, end, glm::vec3(0.35f), 0, false});
    for (const crowd::Polygon& p : w.obstacles) out.push_back({p.vertices, 0, end, glm::vec3(0.30f), 0.35f, false});
    // Goals in the agent's colour while it is in the run: a sequence's goals small, its last one larger.
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const crowd::AgentTrack& track = r.tracks[a];
        const double until = double(track.samples.size()) * r.dt;
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
        for (int a : {it->a, it->b}) {
            const auto& d = r.tracks[std::size_t(a)].samples[std::size_t(frame)];
            out.push_back({circle(d[1], d[2], d[3] + 0.04, 24), t, t, glm::vec3(0.95f, 0.1f, 0.1f), 0, true});
        }
    return out;
}

std::vector<TimelineMark> timeline_marks(const CrowdView& v) {
    std::vector<TimelineMark> out;
    for (std::size_t k = 0; k < v.record.choices.size(); ++k) {
        const crowd::ChoicePoint& c = v.record.choices[k];
        if (c.fallback) out.push_back({TimelineMark::Fallback, c.frame, c.agent, int(k), 1});
    }
    for (const crowd::Contact& c : v.contacts) {
        if (!out.empty() && out.back().kind == TimelineMark::Contact && out.back().frame == c.frame)
            ++out.back().count;
        else
            out.push_back({TimelineMark::Contact, c.frame, c.a, -1, 1});
    }
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
    s.scene.cursor = (double(m.frame) + 0.5) * v.record.dt;
}

}  // namespace mobb::viewer
