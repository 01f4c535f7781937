#include "crowd_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "frame.h"

namespace mobb::viewer {

namespace {

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

double end_time(const crowd::PlacedClip& p, const crowd::MotionGraph& g) {
    return p.place.t0 + g.clips[std::size_t(p.clip)].path.duration();
}

}  // namespace

State load_crowd_state(const std::string& record_file, float aspect) {
    auto view = std::make_shared<CrowdView>();
    view->record = crowd::load_record(record_file);
    const crowd::Record& r = view->record;
    try {
        view->graph = std::make_shared<crowd::MotionGraph>(crowd::load_graph(r.graph));
    } catch (const std::exception& e) {
        view->graph_error = e.what();
    }
    State s;
    s.scene.query_a = s.scene.query_b = -1;
    s.scene.layers.skeletons = false;
    s.scene.layers.trace = false;
    s.scene.width = 960;
    s.scene.height = 540;
    view->agents = int(r.tracks.size());
    s.crowd = view;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        Path path;
        path.dt = r.dt;
        for (const auto& q : r.tracks[a].samples) path.samples.push_back({q[1], q[2], q[3]});
        if (path.samples.empty()) throw std::runtime_error(record_file + ": agent " + std::to_string(a) + " has no samples");
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
    std::stable_sort(out.begin(), out.end(),
                     [&](int a, int b) { return v.record.choices[std::size_t(a)].frame < v.record.choices[std::size_t(b)].frame; });
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
                const bool ok = !cand.outside && cand.hits == 0;
                const glm::vec3 color = cand.clip == c.taken ? kCommitted : ok ? kAccepted : kRejected;
                if (cand.clip < 0 || std::size_t(cand.clip) >= v.graph->clips.size()) continue;
                v.candidate_clips.push_back(add_clip(s, "candidate clip " + std::to_string(cand.clip),
                                                     v.graph->clips[std::size_t(cand.clip)].path, at->place, color));
                v.accepted.push_back(ok);
            }
        }
    }
    ++s.revision;
}

bool open_candidate_query(State& s, int k, std::string* message) {
    CrowdView& v = *s.crowd;
    auto fail = [&](const std::string& m) {
        if (message) *message = m;
        return false;
    };
    if (v.choice < 0) return fail("no choice point selected");
    if (!v.graph) return fail("the record's graph cannot be read: " + v.graph_error);
    if (k < 0 || std::size_t(k) >= v.candidate_clips.size()) return fail("no such candidate");
    const crowd::ChoicePoint& c = v.record.choices[std::size_t(v.choice)];
    const crowd::PlacedClip* at = committed_at(v, c);
    if (!at) return fail("the record has no committed clip at this choice point");
    // Keep the candidates, drop an earlier opened query's other clip.
    const std::size_t keep = std::size_t(v.candidate_clips.back()) + 1;
    s.clips.resize(keep);
    s.places.resize(keep);
    s.fixed_paths.resize(keep);
    s.colors.resize(keep);
    const int a = v.candidate_clips[std::size_t(k)];
    const Tree& ta = *s.clips[std::size_t(a)].tree;
    const double a0 = at->place.t0, a1 = a0 + ta.path().duration();
    const crowd::PlacedClip* pick = nullptr;
    int pick_agent = -1;
    bool pick_hits = false;
    for (std::size_t o = 0; o < v.record.tracks.size() && !pick_hits; ++o) {
        if (int(o) == c.agent) continue;
        for (const crowd::PlacedClip& p : v.record.tracks[o].clips) {
            if (p.commit >= at->commit || p.clip < 0 || std::size_t(p.clip) >= v.graph->clips.size()) continue;
            if (!times_overlap(a0, a1, p.place.t0, end_time(p, *v.graph))) continue;
            const Tree tb = Tree::build(v.graph->clips[std::size_t(p.clip)].path, s.scene.tree);
            const bool hits = collide(ta, at->place, tb, p.place);
            if (!pick || (hits && !pick_hits)) {
                pick = &p;
                pick_agent = int(o);
                pick_hits = hits;
            }
            if (pick_hits) break;
        }
    }
    if (!pick) return fail("no other agent's committed clip overlaps this candidate in time");
    const int b = add_clip(s, "agent " + std::to_string(pick_agent) + " clip " + std::to_string(pick->clip),
                           v.graph->clips[std::size_t(pick->clip)].path, pick->place, render::clip_color(pick_agent));
    s.scene.query_a = a;
    s.scene.query_b = b;
    run_query(s);
    s.scene.step = 0;
    if (message)
        *message = "candidate clip " + std::to_string(c.candidates[std::size_t(k)].clip) + " vs agent " +
                   std::to_string(pick_agent) + (s.answer ? ": collide" : ": clear");
    return true;
}

void update_crowd_playback(State& s, double seconds) {
    if (!s.crowd || !s.crowd->playing) return;
    const double end = double(s.crowd->record.frames) * s.crowd->record.dt;
    s.scene.cursor += seconds * double(s.crowd->rate);
    if (end > 0 && s.scene.cursor > end) s.scene.cursor = std::fmod(s.scene.cursor, end);
}

}  // namespace mobb::viewer
