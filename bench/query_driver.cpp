// Runs N queries of one method on one workload, for instruction counts under callgrind:
//   valgrind --tool=callgrind --toggle-collect=mobb_run_queries build/bench/mobb_query_driver SET METHOD N
// SET: a query-set file (`mobb bench WORKLOAD --save-queries FILE`) or a workload name (table1, table2,
// synth42, synth120, seq42-30, seq42-60: src/bench/tables.h). METHOD: a key or a label of
// src/bench/method.h ("sweep", "MOBB 1 level", ...). N: the first N queries (all when 0 or more than
// the set holds).
// Only mobb_run_queries is measured (loading and preparing the method are excluded): divide its
// instructions by the count printed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "method.h"
#include "query_set.h"
#include "tables.h"

extern "C" __attribute__((noinline)) std::size_t mobb_run_queries(const void* set, const void* method, std::size_t n) {
    const auto& s = *static_cast<const mobb::bench::QuerySet*>(set);
    const auto& m = *static_cast<const mobb::bench::QueryMethod*>(method);
    std::size_t hits = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const mobb::bench::ClipQuery& q = s.queries[k];
        hits += m.query(q.a, q.pa, q.b, q.pb, nullptr);
    }
    return hits;
}

int main(int argc, char** argv) {
    using namespace mobb::bench;
    if (argc != 4) {
        std::fprintf(stderr, "usage: mobb_query_driver SET METHOD N\n");
        return 2;
    }
    try {
        const std::string name = argv[1];
        const QuerySet set = std::filesystem::exists(name) ? load_query_set(name) : named_query_set(name, MOBB_GRAPH);
        if (set.queries.empty()) throw std::runtime_error(name + ": no queries");
        auto method = make_method(parse_method(argv[2]));
        if (!method->unavailable().empty()) throw std::runtime_error(method->unavailable());
        method->prepare(set.clips);
        const long long asked = std::atoll(argv[3]);
        const std::size_t n = asked > 0 ? std::min(std::size_t(asked), set.queries.size()) : set.queries.size();
        const std::size_t hits = mobb_run_queries(&set, method.get(), n);
        std::printf("queries %zu hits %zu\n", n, hits);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mobb_query_driver: %s\n", e.what());
        return 1;
    }
    return 0;
}
