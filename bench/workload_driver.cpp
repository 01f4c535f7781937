// Runs the first N queries of a saved workload (mobb bench WORKLOAD --save-queries FILE) with one
// method, for instruction counts under callgrind (bench/callgrind_workload.sh):
//   valgrind --tool=callgrind --toggle-collect=mobb_workload_queries
//            build/bench/mobb_workload_driver FILE "MOBB 1 level" 5000
// Only mobb_workload_queries is measured (loading and preparing the method are excluded); divide its
// instructions by the count printed. N larger than the set is cut to the set's size.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "mobb/crowd/bench_tables.h"

extern "C" __attribute__((noinline)) std::size_t mobb_workload_queries(const void* set, const void* method, std::size_t n) {
    const auto& s = *static_cast<const mobb::crowd::QuerySet*>(set);
    const auto& m = *static_cast<const mobb::crowd::QueryMethod*>(method);
    std::size_t hits = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const mobb::crowd::BenchQuery& q = s.queries[k];
        hits += m.query(q.a, q.pa, q.b, q.pb, nullptr);
    }
    return hits;
}

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: mobb_workload_driver QUERY_SET METHOD N\n");
        return 2;
    }
    try {
        const mobb::crowd::QuerySet set = mobb::crowd::load_query_set(argv[1]);
        auto method = mobb::crowd::method_by_name(argv[2]);
        if (!method->unavailable().empty()) throw std::runtime_error(method->unavailable());
        method->prepare(set.clips);
        const std::size_t n = std::min(set.queries.size(), std::size_t(std::atoll(argv[3])));
        const std::size_t hits = mobb_workload_queries(&set, method.get(), n);
        std::printf("queries %zu hits %zu\n", n, hits);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mobb_workload_driver: %s\n", e.what());
        return 1;
    }
    return 0;
}
