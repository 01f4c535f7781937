// Writing a crowd record as JSON (the layout in include/mobb/crowd/record/record.h).
#include "mobb/crowd/record/record.h"

#include <nlohmann/json.hpp>

#include "mobb/util/json_text.h"
#include "record/record_json.h"

namespace mobb::crowd {

namespace {

using J = nlohmann::ordered_json;

J world_json(const World& w) {
    if (w.x0 == 0 && w.y0 == 0) return {w.x1, w.y1};
    return {w.x0, w.y0, w.x1, w.y1};
}

J obstacles_json(const World& w) {
    J out = J::array();
    for (const Polygon& p : w.obstacles) {
        J poly = J::array();
        for (const auto& v : p.vertices) poly.push_back({v[0], v[1]});
        out.push_back(poly);
    }
    return out;
}

J track_json(const AgentTrack& t) {
    J clips = J::array();
    for (const PlacedClip& c : t.clips)
        clips.push_back({{"clip", c.clip},
                         {"start", c.start},
                         {"place", {c.place.x, c.place.y, c.place.theta, c.place.t0}},
                         {"fallback", c.fallback},
                         {"choice", c.choice}});
    J samples = J::array();
    for (const auto& s : t.samples) samples.push_back({s[0], s[1], s[2], s[3]});
    J out = J::object();
    if (t.goals.size() == 1) out["goal"] = {t.goals[0][0], t.goals[0][1]};
    if (t.goals.size() > 1) {
        out["goals"] = J::array();
        for (const auto& g : t.goals) out["goals"].push_back({g[0], g[1]});
    }
    if (t.at_goal == AtGoal::Leave) out["at_goal"] = to_string(t.at_goal);
    if (t.left_frame) out["left_frame"] = *t.left_frame;
    out["clips"] = clips;
    out["samples"] = samples;
    return out;
}

J escape_json(const std::vector<FramedClip>& clips) {
    J escape = J::array();
    for (const FramedClip& e : clips) escape.push_back({e.clip, e.frame, e.place.x, e.place.y, e.place.theta});
    return escape;
}

J hold_json(const std::array<double, 3>& h, std::int64_t frame) { return {h[0], h[1], h[2], frame}; }

J plan_json(const ChoicePoint& c) {
    J out = {{"escape", escape_json(c.escape)}};
    if (c.holds) out["hold"] = hold_json(c.hold, c.hold_frame);
    if (!c.intended.empty()) out["intended"] = escape_json(c.intended);
    if (c.reroutes.empty()) return out;
    J reroutes = J::array();
    for (const ReroutedPlan& r : c.reroutes)
        reroutes.push_back(
            {{"agent", r.agent}, {"escape", escape_json(r.escape)}, {"hold", hold_json(r.hold, r.hold_frame)}});
    out["reroutes"] = reroutes;
    return out;
}

J choice_json(const ChoicePoint& c, double dt) {
    J cands = J::array();
    for (const Candidate& k : c.candidates) {
        J against = J::array();
        for (const CandidateQuery& q : k.against)
            against.push_back({q.agent, query_index(q), q.piece, q.mine, int(q.hit)});
        cands.push_back({{"clip", k.clip},
                         {"leaves_world", k.leaves_world},
                         {"meets_solid", k.meets_solid},
                         {"queries", k.queries},
                         {"hits", k.hits},
                         {"against", against}});
        if (k.crowded) cands.back()["crowded"] = true;
    }
    return {{"agent", c.agent},     {"frame", c.frame},     {"t", util::rounded(double(c.frame) * dt, 9)},
            {"taken", c.taken},     {"outcome", c.outcome}, {"fallback", c.fallback},
            {"queries", c.queries}, {"tests2d", c.tests2d}, {"tests3d", c.tests3d},
            {"samples", c.samples}, {"pruned", c.pruned},   {"plan", plan_json(c)},
            {"candidates", cands}};
}

}  // namespace

nlohmann::ordered_json record_json(const Record& r, const std::string& summary_json, const std::string& metrics_json) {
    J j;
    j["format"] = "mobb crowd record";
    j["version"] = kRecordVersion;
    j["graph"] = r.graph;
    j["dt"] = r.dt;
    j["frames"] = r.frames;
    j["agents"] = r.tracks.size();
    j["seed"] = r.seed;
    j["tree"] = r.tree;
    j["select"] = r.select;
    if (!r.scenario.empty()) j["scenario"] = r.scenario;
    j["world"] = world_json(r.world);
    j["walls"] = r.world.walls;
    j["obstacles"] = obstacles_json(r.world);
    j["summary"] = summary_json.empty() ? J::object() : J::parse(summary_json);
    if (!metrics_json.empty()) j["metrics"] = J::parse(metrics_json);
    J tracks = J::array();
    for (const AgentTrack& t : r.tracks) tracks.push_back(track_json(t));
    j["tracks"] = tracks;
    J choices = J::array();
    for (const ChoicePoint& c : r.choices) choices.push_back(choice_json(c, r.dt));
    j["choices"] = choices;
    return j;
}

std::string record_to_text(const Record& r, const std::string& summary_json, const std::string& metrics_json) {
    return util::readable_json(record_json(r, summary_json, metrics_json));
}

}  // namespace mobb::crowd
