#include "steersuite_cases.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bar_chart.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/scenario/steersuite.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/json_text.h"

namespace mobb::bench {

using util::fixed;

namespace {

// Agents a note says were left out (steersuite.h: one line per finding, ending so).
int left_out_of(const std::vector<std::string>& notes) {
    int n = 0;
    for (const std::string& note : notes) n += note.find("left out") != std::string::npos;
    return n;
}

std::vector<crowd::AgentStart> starts_of(const crowd::Scenario& s) {
    std::vector<crowd::AgentStart> out;
    for (const crowd::AgentSpec& a : s.agents) out.push_back({{a.start.x, a.start.y}, a.start_time});
    return out;
}

CaseRow run_case(const crowd::MotionGraph& g, const crowd::NarrowPhase& narrow, const crowd::AgentRoom& room,
                 const std::string& file, std::uint64_t seed, int threads) {
    CaseRow row;
    row.name = std::filesystem::path(file).stem().string();
    row.seed = seed;
    crowd::ImportedScenario imported;
    try {
        imported = crowd::import_steersuite(file, room, {seed, 0, crowd::AtGoal::Leave});
    } catch (const std::exception& e) {
        row.error = e.what();
        return row;
    }
    row.imported = true;
    row.notes = imported.notes;
    row.left_out = left_out_of(imported.notes);
    const crowd::Scenario& s = imported.scenario;
    row.agents = int(s.agents.size());
    row.time_limit = s.time_limit;
    if (s.agents.empty()) {
        row.error = "no agent left to run";
        return row;
    }
    crowd::CrowdOptions o = crowd::scenario_options(s);
    o.seed = seed;
    o.threads = threads;
    o.record_queries = false;
    const auto start = std::chrono::steady_clock::now();
    try {
        const crowd::CrowdRun run = crowd::run_crowd(g, narrow, o);
        row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        row.metrics = crowd::crowd_metrics(run.record, g, o.goal_radius);
        row.verdict = crowd::judge_run(run.record, starts_of(s), s.time_limit, row.metrics);
    } catch (const std::invalid_argument& e) {  // agents the crowd cannot start where the case puts them
        row.error = e.what();
    }
    return row;
}

// A case is empty when it imports on every seed without an agent and left none out: a map alone.
bool empty_run(const CaseRow& r) { return r.imported && r.agents == 0 && r.left_out == 0; }

void count_cases(SteerSuiteTable& t) {
    struct Case {
        bool passed = true, empty = true;  // on every seed
    };
    std::map<std::string, Case> cases;
    for (const CaseRow& r : t.rows) {
        Case& c = cases[r.name];
        c.passed = c.passed && r.error.empty() && r.verdict.passed;
        c.empty = c.empty && empty_run(r);
    }
    for (const auto& [name, c] : cases) {
        if (c.empty) {
            t.empty.push_back(name);
            continue;
        }
        ++t.cases;
        t.cases_passed += c.passed;
    }
    int imported = 0, contacts = 0;
    for (const CaseRow& r : t.rows) imported += r.imported, contacts += int(r.metrics.contacts);
    t.targets.push_back(at_least("runs whose file imports", double(t.rows.size()), imported, "every file, every seed"));
    t.targets.push_back(at_most("contact frames, every run", 0, contacts, "agent pairs x frames"));
    t.targets.push_back(at_least("% of the cases passing the judge on every seed", 90,
                                 t.cases ? 100.0 * t.cases_passed / t.cases : 0.0,
                                 std::to_string(t.cases_passed) + " of " + std::to_string(t.cases) + " with agents"));
    for (Target& g : t.targets) g.ratio = false;  // counts and shares
}

}  // namespace

SteerSuiteTable run_steersuite(const SteerSuiteOptions& o, const std::function<void(double)>& progress) {
    const crowd::MotionGraph g = crowd::load_graph(o.graph);
    const crowd::NarrowPhase narrow = crowd::NarrowPhase::sweep(g);
    const crowd::AgentRoom room = crowd::AgentRoom::of(g);
    SteerSuiteTable t;
    const double total = double(o.cases.size() * o.seeds.size());
    for (const std::string& file : o.cases)
        for (std::uint64_t seed : o.seeds) {
            t.rows.push_back(run_case(g, narrow, room, file, seed, o.threads));
            if (progress) progress(double(t.rows.size()) / total);
        }
    count_cases(t);
    return t;
}

std::string steersuite_markdown(const SteerSuiteTable& t) {
    std::ostringstream out;
    out << "| case | seed | agents (left out) | passed | on time / goal agents | contacts | solids | time to goal / "
           "straight | idle % | Composite01 | Composite02 | wall s | why not |\n"
        << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for (const CaseRow& r : t.rows) {
        const crowd::CrowdMetrics& m = r.metrics;
        const crowd::Verdict& v = r.verdict;
        out << "| " << r.name << " | " << r.seed << " | " << r.agents << " (" << r.left_out << ") | ";
        if (!r.error.empty()) {
            out << "NO | - | - | - | - | - | - | - | - | " << r.error << " |\n";
            continue;
        }
        out << (v.passed ? "yes" : "NO") << " | " << v.on_time << " / " << v.goal_agents << " | " << m.contacts << " | "
            << m.obstacle_contacts << " | " << fixed(m.time_ratio, 2) << " | " << fixed(100 * m.idle_share, 1) << " | "
            << fixed(m.composite01, 1) << " | " << fixed(m.composite02, 1) << " | " << fixed(r.wall_seconds, 1) << " | "
            << v.reason << " |\n";
    }
    out << "\n" << t.cases_passed << " of " << t.cases << " cases pass on every seed.";
    for (const std::string& name : t.empty) out << " " << name << " imports without an agent: nothing to judge.";
    out << "\n\nTargets (issue 45):\n\n";
    for (const Target& g : t.targets) out << "- " << g.what << ": " << target_text(g) << " (" << g.detail << ")\n";
    return out.str();
}

std::string steersuite_json(const SteerSuiteTable& t) {
    using J = nlohmann::ordered_json;
    J rows = J::array();
    for (const CaseRow& r : t.rows) {
        // The import's notes, the first kNotes of them: maps of thousands of obstacles note every narrow gap.
        constexpr std::size_t kNotes = 20;
        const std::vector<std::string> notes(r.notes.begin(),
                                             r.notes.begin() + std::ptrdiff_t(std::min(kNotes, r.notes.size())));
        J j = {{"case", r.name},         {"seed", r.seed}, {"agents", r.agents},
               {"left_out", r.left_out}, {"notes", notes}, {"notes_total", r.notes.size()}};
        if (!r.error.empty()) {
            j["error"] = r.error;
        } else {
            const crowd::Verdict& v = r.verdict;
            j["time_limit"] = r.time_limit;
            j["wall_seconds"] = util::rounded(r.wall_seconds, 3);
            j["passed"] = v.passed;
            j["judge"] = {{"goal_agents", v.goal_agents}, {"on_time", v.on_time}, {"never", v.never}, {"late", v.late},
                          {"strayed", v.strayed},         {"reason", v.reason}};
            j["metrics"] = J::parse(crowd::metrics_json(r.metrics));
        }
        rows.push_back(std::move(j));
    }
    J targets = J::array();
    for (const Target& g : t.targets)
        targets.push_back({{"target", g.what}, {"goal", g.goal}, {"measured", g.measured}, {"met", g.met()}});
    const J j = {{"workload", "steersuite"},        {"cases", t.cases}, {"cases_passed", t.cases_passed},
                 {"cases_without_agents", t.empty}, {"rows", rows},     {"targets", targets}};
    return util::readable_json(j);
}

void write_steersuite_png(const SteerSuiteTable& t, const std::string& file) {
    std::vector<Bar> bars;
    for (const CaseRow& r : t.rows)
        bars.push_back({r.name + " s" + std::to_string(r.seed) + (r.verdict.passed ? "" : " (fails)"),
                        r.error.empty() ? r.metrics.time_ratio : 0.0});
    write_bar_chart(file, "SteerSuite's test cases: time to goal over the straight line", bars, "x");
}

}  // namespace mobb::bench
