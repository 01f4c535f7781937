// SteerSuite's test cases as a benchmark (`mobb bench steersuite DIR`): every test case of a folder
// (SteerSuite/Release testcases/*.xml, the schema's files) imported as `mobb scenario import` reads it and
// run with several seeds (the seed draws the case's random parts too), each judged by the per-agent judge
// (crowd/metrics/judge.h) and scored with SteerSuite's composites (CrowdMetrics). Issue 45's target: at
// least 90 % of the cases pass on every seed.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mobb/crowd/metrics/judge.h"
#include "mobb/crowd/metrics/metrics.h"
#include "targets.h"

namespace mobb::bench {

struct SteerSuiteOptions {
    std::string graph;
    std::vector<std::string> cases;  ///< test-case files (XML)
    std::vector<std::uint64_t> seeds = {1, 2, 3};
    int threads = 1;  ///< per run
};

/// One case run with one seed; a case that does not import, or imports without an agent, has only `error`.
struct CaseRow {
    std::string name, error;
    bool imported = false;  ///< the file imports (it may still hold no agent: a map alone)
    std::uint64_t seed = 0;
    int agents = 0;    ///< run
    int left_out = 0;  ///< agents of the file the import left out (each said in a note)
    std::vector<std::string> notes;
    double time_limit = 0, wall_seconds = 0;
    crowd::CrowdMetrics metrics;
    crowd::Verdict verdict;
};

struct SteerSuiteTable {
    std::vector<CaseRow> rows;
    /// Cases to judge: those that import with agents, or fail to import (a case passes when every seed's
    /// run does). A file that imports without an agent (a map alone) has nothing to judge: in `empty`.
    int cases = 0, cases_passed = 0;
    std::vector<std::string> empty;
    std::vector<Target> targets;
};

/// Runs every case with every seed; `progress` (may be empty) gets the fraction done.
SteerSuiteTable run_steersuite(const SteerSuiteOptions& o, const std::function<void(double)>& progress = {});

std::string steersuite_markdown(const SteerSuiteTable& t);
std::string steersuite_json(const SteerSuiteTable& t);
/// Bar chart of each run's time to goal over the straight line (0 where it did not run).
void write_steersuite_png(const SteerSuiteTable& t, const std::string& file);

}  // namespace mobb::bench
