// The crowd quality workload (crowd_quality.h).
#include "crowd_quality.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bar_chart.h"
#include "machine.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/json_text.h"
#include "mobb/util/worker_pool.h"

namespace mobb::bench {

namespace {

using util::fixed;

// Before the escapes: 10,013 contact agent-pair frames at 100 agents, 30 x 40 m, 60 s, seed 11.
constexpr double kContactsBefore = 10013.0 / 60.0;  // per simulated second

// The motion metrics of a run when it has at most o.motion_agents agents and the mocap is at hand (else
// nothing, and a note says why). They run after the crowd, on every core: the CD cost is not affected.
std::optional<crowd::CrowdMotion> measure_motion(const crowd::Record& r,
                                                 const std::shared_ptr<const crowd::MotionGraph>& g,
                                                 const CrowdQualityOptions& o, std::string& note) {
    if (int(r.tracks.size()) > o.motion_agents) return std::nullopt;
    try {
        return crowd::crowd_motion(r, g, crowd::PoseBlend{}.window, util::WorkerPool::hardware_threads());
    } catch (const io::LoadError& e) {
        note = std::string("not measured: ") + e.what();
    } catch (const crowd::GraphError& e) {
        note = std::string("not measured: ") + e.what();
    }
    return std::nullopt;
}

WanderRow run_wander(const std::shared_ptr<const crowd::MotionGraph>& g, const crowd::NarrowPhase& narrow,
                     const CrowdQualityOptions::Wander& w, std::uint64_t seed, const CrowdQualityOptions& opt,
                     std::string& note) {
    crowd::CrowdOptions o;
    o.agents = w.agents;
    o.world.x1 = w.width;
    o.world.y1 = w.height;
    o.seconds = w.seconds;
    o.seed = seed;
    o.threads = opt.threads;
    o.record_queries = false;  // the metrics read the tracks and the choice points' counts
    const crowd::CrowdRun run = crowd::run_crowd(*g, narrow, o);
    return {w.agents,
            w.width,
            w.height,
            w.seconds,
            seed,
            crowd::crowd_metrics(run.record, *g, o.goal_radius),
            run.summary.escapes,
            run.summary.cd_us_per_agent_second(),
            measure_motion(run.record, g, opt, note)};
}

ScenarioRow run_scenario(const std::shared_ptr<const crowd::MotionGraph>& g, const crowd::NarrowPhase& narrow,
                         const std::string& file, std::uint64_t seed, const CrowdQualityOptions& opt,
                         std::string& note) {
    const crowd::Scenario s = crowd::load_scenario(file);
    crowd::CrowdOptions o = crowd::scenario_options(s);
    o.seed = seed;
    o.threads = opt.threads;
    o.record_queries = false;
    const crowd::CrowdRun run = crowd::run_crowd(*g, narrow, o);
    return {s.name,
            std::filesystem::path(file).filename().string(),
            int(s.agents.size()),
            s.time_limit,
            seed,
            crowd::crowd_metrics(run.record, *g, o.goal_radius),
            measure_motion(run.record, g, opt, note)};
}

void add_wander_targets(CrowdQualityTable& t, const CrowdQualityOptions& o) {
    double fallbacks = 0, big_fallbacks = 0, unexcused = 0, contacts = 0, outside = 0, speed = 1e300, idle = 0,
           longest = 0, cost = 0;
    bool big = false;
    for (const WanderRow& r : t.wander) {
        const crowd::CrowdMetrics& m = r.metrics;
        if (r.agents <= 1000) {
            fallbacks = std::max(fallbacks, m.fallback_share);
            unexcused += double(m.contacts_outside_fallbacks);
            contacts = std::max(contacts, double(m.contacts) / r.seconds);
            outside += double(m.samples_outside + m.obstacle_contacts);
        } else {
            big = true;
            big_fallbacks = std::max(big_fallbacks, m.fallback_share);
            cost = std::max(cost, r.cd_us_per_agent_second);
        }
        speed = std::min(speed, m.speed_ratio);
        idle = std::max(idle, m.idle_share);
        longest = std::max(longest, m.longest_idle);
    }
    const std::string seeds = "worst of seeds " + std::to_string(o.seeds.size());
    t.targets.push_back(
        at_most("wander 100 and 1,000 agents: fallbacks <= 0.5 % of choice points (%)", 0.5, 100 * fallbacks, seeds));
    t.targets.push_back(at_most("wander 100 and 1,000 agents: contacts outside fallbacks", 0, unexcused, "all runs"));
    t.targets.push_back(at_most("wander: contact agent-pair frames per simulated second, 100x fewer than before (" +
                                    fixed(kContactsBefore, 1) + ")",
                                kContactsBefore / 100, contacts, seeds));
    t.targets.push_back(at_most("wander: samples outside the world or on a wall", 0, outside, "all runs"));
    t.targets.push_back(at_most("wander 10,000 agents: fallbacks <= 0.5 % (%)", 0.5, 100 * big_fallbacks, seeds));
    t.targets.back().known = big;
    t.targets.push_back(at_least("wander: mean ground speed / the graph's mean clip speed >= 0.8", 0.8, speed, seeds));
    t.targets.push_back(at_most("wander: idle share of agent time <= 10 % (%)", 10, 100 * idle, seeds));
    t.targets.push_back(at_most("wander: longest idle stretch <= 5 s", 5, longest, seeds));
    Target c = at_most("CD per agent per simulated second at 10,000 agents <= 2x before (" + fixed(o.baseline_us, 2) +
                           " us, MOBB tree, 1 thread)",
                       2, cost / o.baseline_us, fixed(cost, 2) + " us, 1 thread, circle sweep", true);
    c.known = big && cost > 0;
    t.targets.push_back(c);
}

// Issue 28: the worst scenario run's time to goal over the straight line at walking speed, and idle share
// (at-goal time left out).
void add_goal_quality_targets(CrowdQualityTable& t) {
    const ScenarioRow* slowest = nullptr;
    const ScenarioRow* idlest = nullptr;
    for (const ScenarioRow& r : t.scenarios) {
        if (!slowest || r.metrics.time_ratio > slowest->metrics.time_ratio) slowest = &r;
        if (!idlest || r.metrics.idle_share > idlest->metrics.idle_share) idlest = &r;
    }
    if (!slowest) return;
    const auto where = [](const ScenarioRow& r) { return r.name + " seed " + std::to_string(r.seed); };
    t.targets.push_back(
        at_most("mean time to goal <= 1.5x the straight line at the graph's walking speed, every scenario", 1.5,
                slowest->metrics.time_ratio, "worst: " + where(*slowest), true));
    t.targets.push_back(at_most("idle <= 20 % of agent time (at-goal time left out), every scenario", 20,
                                100 * idlest->metrics.idle_share, "worst: " + where(*idlest) + ", in %"));
}

void add_scenario_target(CrowdQualityTable& t) {
    int passed = 0;
    std::string failed;
    for (const ScenarioRow& r : t.scenarios) {
        passed += r.metrics.passed;
        if (!r.metrics.passed) failed += (failed.empty() ? "" : ", ") + r.name + " seed " + std::to_string(r.seed);
    }
    Target s = at_least("scenarios passed (every agent at its goal in time, no contact)", double(t.scenarios.size()),
                        passed, failed.empty() ? "every run" : "failed: " + failed);
    s.ratio = false;
    t.targets.push_back(s);
    add_goal_quality_targets(t);
}

// The worst of `value` over every run measured, and the run.
template <typename F>
std::pair<double, std::string> worst_run(const CrowdQualityTable& t, F value) {
    std::pair<double, std::string> worst{-1e300, ""};
    const auto see = [&](const std::optional<crowd::CrowdMotion>& m, const std::string& run) {
        if (!m || !m->blended.feet) return;
        const double v = value(*m);
        if (v > worst.first) worst = {v, run};
    };
    for (const WanderRow& r : t.wander)
        see(r.motion, "wander " + std::to_string(r.agents) + " seed " + std::to_string(r.seed));
    for (const ScenarioRow& r : t.scenarios) see(r.motion, r.name + " seed " + std::to_string(r.seed));
    return worst;
}

// Issue 47's feet targets: GMD's skating share of the poses shown at most the raw clips' for every kind of
// clip; planted feet (found contacts) sliding at most 1 cm per frame (p99) and the IK's residual p99 at
// most 1 cm; every run measured, the worst kind of the worst run.
void add_feet_targets(CrowdQualityTable& t) {
    const auto over_kinds = [](const crowd::CrowdMotion& m, auto value) {
        double worst = -1e300;
        for (std::size_t k = 0; k < m.blended.sliding.size(); ++k)
            if (m.blended.sliding[k].contact > 0) worst = std::max(worst, value(m, k));
        return worst;
    };
    const auto skate = worst_run(t, [&](const crowd::CrowdMotion& m) {
        return over_kinds(m, [](const crowd::CrowdMotion& x, std::size_t k) {
            return 100 * (x.blended.sliding[k].skate_share - x.raw.sliding[k].skate_share);
        });
    });
    const auto slide = worst_run(t, [&](const crowd::CrowdMotion& m) {
        return over_kinds(m,
                          [](const crowd::CrowdMotion& x, std::size_t k) { return 100 * x.blended.hold[k].slide.p99; });
    });
    const auto residual = worst_run(t, [&](const crowd::CrowdMotion& m) {
        return over_kinds(
            m, [](const crowd::CrowdMotion& x, std::size_t k) { return 100 * x.blended.hold[k].residual.p99; });
    });
    const std::pair<const char*, std::pair<double, std::string>> rows[] = {
        {"feet: skating share (GMD) of the poses shown minus the raw clips', percentage points, every kind of clip",
         skate},
        {"feet: p99 slide of a planted foot per frame (found contacts), cm, every kind of clip", slide},
        {"feet: p99 IK residual (ankle to its target), cm, every kind of clip", residual}};
    const double goals[] = {0.0, 1.0, 1.0};
    for (std::size_t i = 0; i < 3; ++i) {
        Target x = at_most(rows[i].first, goals[i], rows[i].second.first, "worst: " + rows[i].second.second);
        x.known = !rows[i].second.second.empty();
        t.targets.push_back(x);
    }
}

// Issue 30's pops target: blended, the p99 joint jump at clip starts at most 1.2x the p99 within clips,
// on every run measured (the 100-agent wander and every scenario among them).
void add_motion_target(CrowdQualityTable& t) {
    double worst = 0;
    std::string where;
    const auto see = [&](const std::optional<crowd::CrowdMotion>& m, const std::string& run) {
        if (m && m->blended.jump_ratio() >= worst) {
            worst = m->blended.jump_ratio();
            where = run;
        }
    };
    for (const WanderRow& r : t.wander)
        see(r.motion, "wander " + std::to_string(r.agents) + " seed " + std::to_string(r.seed));
    for (const ScenarioRow& r : t.scenarios) see(r.motion, r.name + " seed " + std::to_string(r.seed));
    Target m = at_most("pops: p99 joint jump at clip starts <= 1.2x the p99 within clips, blended, every run measured",
                       1.2, worst, "worst: " + where, true);
    m.known = !where.empty();
    t.targets.push_back(m);
    add_feet_targets(t);
}

std::string spread_cell(const crowd::Spread& s) { return fixed(s.median, 3) + " / " + fixed(s.p99, 3); }

void motion_rows(std::ostream& out, const std::string& run, std::uint64_t seed, const crowd::CrowdMotion& m) {
    const std::pair<const crowd::MotionMetrics*, const char*> rows[] = {
        {&m.raw, "raw"}, {&m.unlocked, "free"}, {&m.blended, m.blended.locked ? "locked" : "free"}};
    for (const auto& [x, feet] : rows) {
        if (x == &m.unlocked && !m.blended.locked) continue;  // the same poses as the row after
        out << "| " << run << " | " << seed << " | " << (x->blend > 0 ? fixed(x->blend, 2) : "off") << " | " << feet
            << " | " << x->jump_start.count << " | " << spread_cell(x->jump_start) << " | "
            << spread_cell(x->jump_within) << " | " << fixed(x->jump_ratio(), 2) << " | " << fixed(x->knee_start.p99, 3)
            << " / " << fixed(x->knee_within.p99, 3) << " |";
        for (const crowd::FootSliding& f : x->sliding)
            out << " " << (f.contact ? spread_cell(f.speed) + ", " + fixed(100 * f.skate_share, 1) : "-") << " |";
        std::string slide, residual;
        for (std::size_t k = 0; k < x->hold.size(); ++k) {
            const std::string sep = k ? " / " : "";
            slide += sep + (x->hold[k].slide.count ? fixed(100 * x->hold[k].slide.p99, 2) : "-");
            residual += sep + (x->hold[k].residual.count ? fixed(100 * x->hold[k].residual.p99, 2) : "-");
        }
        out << " " << slide << " | " << residual << " |\n";
    }
}

void motion_markdown(const CrowdQualityTable& t, std::ostream& out) {
    out << "\n### Motion (poses: joint jumps and foot sliding; raw clips, blended, blended with feet locked)\n\n"
        << "Joint jump: per agent and frame the largest move of a joint relative to the root (m); knee: the largest "
           "change of a knee's angle per frame (rad, p99 at clip starts / within clips); foot sliding: a toe's "
           "horizontal speed while in contact by GMD's rule (m/s) and the share of contact steps skating (%), by the "
           "kind of clip played; planted: the planted point's move per frame during the contacts found in the "
           "mocap (p99, cm) and the IK's residual (p99, cm), walk / slow / in place / idle.\n\n"
        << "| run | seed | blend s | feet | clip starts | jump at starts median / p99 | within clips median / p99 | "
           "p99 ratio | knee p99 | walk: sliding median / p99, skating % | slow | in place | idle | planted slide "
           "p99 cm | IK residual p99 cm |\n"
        << "|---|---:|---:|---|---:|---|---|---:|---|---|---|---|---|---|---|\n";
    for (const WanderRow& r : t.wander)
        if (r.motion) motion_rows(out, "wander " + std::to_string(r.agents), r.seed, *r.motion);
    for (const ScenarioRow& r : t.scenarios)
        if (r.motion) motion_rows(out, r.name, r.seed, *r.motion);
}

}  // namespace

CrowdQualityTable run_crowd_quality(const CrowdQualityOptions& o, const std::function<void(double)>& progress) {
    const auto shared = std::make_shared<const crowd::MotionGraph>(crowd::load_graph(o.graph));
    const crowd::MotionGraph& g = *shared;
    const crowd::NarrowPhase narrow = crowd::NarrowPhase::sweep(g);
    std::string motion_note;
    CrowdQualityTable t;
    const double total = double(o.seeds.size() * (o.wander.size() + o.scenarios.size()));
    double done = 0;
    for (const auto& w : o.wander)
        for (std::uint64_t seed : o.seeds) {
            t.wander.push_back(run_wander(shared, narrow, w, seed, o, motion_note));
            if (progress) progress(++done / total);
        }
    for (const std::string& file : o.scenarios)
        for (std::uint64_t seed : o.seeds) {
            t.scenarios.push_back(run_scenario(shared, narrow, file, seed, o, motion_note));
            if (progress) progress(++done / total);
        }
    add_wander_targets(t, o);
    add_scenario_target(t);
    add_motion_target(t);
    t.notes["graph"] = o.graph + " (" + std::to_string(g.clips.size()) + " clips)";
    t.notes["selection"] =
        "wander: mobb crowd --select wander (walled world, no wrap); scenarios: mobb crowd --scenario";
    t.notes["narrow phase"] = "circle sweep (ClipIndex + collide_sweep), " + std::to_string(o.threads) + " thread(s)";
    t.notes["idle"] = "ground speed over a 1 s window below 0.25 m/s; an agent at its goal no longer counts";
    t.notes["cpu"] = cpu_name();
    t.notes["motion"] = motion_note.empty()
                            ? "every agent's pose (all joints) at every frame of runs of at most " +
                                  std::to_string(o.motion_agents) +
                                  " agents: the raw clips, blended (0.25 s), blended with feet locked; " +
                                  "foot contact: toe below 0.05 m, skating above 0.5 m/s (GMD, ICCV 2023)"
                            : motion_note;
    return t;
}

std::string crowd_quality_markdown(const CrowdQualityTable& t) {
    std::ostringstream out;
    out << "### Wandering crowds (wander, walled world)\n\n"
        << "| agents | world (m) | s | seed | choice points | fallbacks % | escapes | contacts | outside | speed / "
           "graph | "
           "idle % | longest idle s | CD us / agent / s |\n"
        << "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const WanderRow& r : t.wander) {
        const crowd::CrowdMetrics& m = r.metrics;
        out << "| " << r.agents << " | " << fixed(r.width, 1) << " x " << fixed(r.height, 1) << " | "
            << fixed(r.seconds, 0) << " | " << r.seed << " | " << m.choice_points << " | "
            << fixed(100 * m.fallback_share, 3) << " | " << r.escapes << " | " << m.contacts << " | "
            << m.samples_outside + m.obstacle_contacts << " | " << fixed(m.speed_ratio, 3) << " | "
            << fixed(100 * m.idle_share, 1) << " | " << fixed(m.longest_idle, 1) << " | "
            << fixed(r.cd_us_per_agent_second, 2) << " |\n";
    }
    out << "\n### Scenarios (goal-directed)\n\n"
        << "| scenario | agents | seed | passed | reached | mean / last time to goal s (limit) | time to goal / "
           "straight at walking speed | contacts | path / straight | speed / graph | idle % | Composite01 | "
           "Composite02 |\n"
        << "|---|---:|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ScenarioRow& r : t.scenarios) {
        const crowd::CrowdMetrics& m = r.metrics;
        out << "| " << r.name << " | " << r.agents << " | " << r.seed << " | " << (m.passed ? "yes" : "NO") << " | "
            << m.reached << " / " << m.goal_agents << " | " << fixed(m.mean_time_to_goal, 1) << " / "
            << fixed(m.max_time_to_goal, 1) << " (" << fixed(r.time_limit, 0) << ") | " << fixed(m.time_ratio, 2)
            << " | " << m.contacts << " | " << fixed(m.path_ratio, 2) << " | " << fixed(m.speed_ratio, 3) << " | "
            << fixed(100 * m.idle_share, 1) << " | " << fixed(m.composite01, 1) << " | " << fixed(m.composite02, 1)
            << " |\n";
    }
    motion_markdown(t, out);
    out << "\nTargets (issues 10, 28 and 30):\n\n";
    for (const Target& g : t.targets) out << "- " << g.what << ": " << target_text(g) << " (" << g.detail << ")\n";
    out << "\n";
    for (const auto& [k, v] : t.notes) out << "- " << k << ": " << v << "\n";
    return out.str();
}

namespace {
// A run's metrics as the record has them: "motion" among them where measured.
nlohmann::ordered_json metrics_of(const crowd::CrowdMetrics& m, const std::optional<crowd::CrowdMotion>& motion) {
    const std::string j = crowd::metrics_json(m);
    return nlohmann::ordered_json::parse(motion ? crowd::with_motion(j, *motion) : j);
}
}  // namespace

std::string crowd_quality_json(const CrowdQualityTable& t) {
    using J = nlohmann::ordered_json;
    J j;
    j["workload"] = "crowd";
    J wander = J::array();
    for (const WanderRow& r : t.wander)
        wander.push_back({{"agents", r.agents},
                          {"world", {r.width, r.height}},
                          {"seconds", r.seconds},
                          {"seed", r.seed},
                          {"escapes", r.escapes},
                          {"cd_us_per_agent_second", util::rounded(r.cd_us_per_agent_second, 4)},
                          {"metrics", metrics_of(r.metrics, r.motion)}});
    J scenarios = J::array();
    for (const ScenarioRow& r : t.scenarios)
        scenarios.push_back({{"scenario", r.name},
                             {"file", r.file},
                             {"agents", r.agents},
                             {"time_limit", r.time_limit},
                             {"seed", r.seed},
                             {"metrics", metrics_of(r.metrics, r.motion)}});
    J targets = J::array();
    for (const Target& g : t.targets)
        targets.push_back({{"target", g.what},
                           {"goal", g.goal},
                           {"measured", g.known ? J(util::rounded(g.measured, 4)) : J()},
                           {"met", g.met()},
                           {"text", target_text(g)},
                           {"detail", g.detail}});
    j["targets"] = targets;
    j["notes"] = t.notes;
    j["wander"] = wander;
    j["scenarios"] = scenarios;
    return util::readable_json(j);
}

void write_crowd_quality_png(const CrowdQualityTable& t, const std::string& file) {
    std::vector<Bar> bars;
    for (const WanderRow& r : t.wander)
        bars.push_back({"wander " + std::to_string(r.agents) + " seed " + std::to_string(r.seed) + " idle %",
                        100 * r.metrics.idle_share});
    for (const ScenarioRow& r : t.scenarios)
        bars.push_back({r.name + " seed " + std::to_string(r.seed) + " last goal s", r.metrics.max_time_to_goal});
    write_bar_chart(file, "Crowd quality: idle % of agent time (wander), seconds to the last goal (scenarios)", bars,
                    "");
}

}  // namespace mobb::bench
