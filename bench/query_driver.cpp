// Runs N queries of one method on the ~42 s workload, for instruction counts:
//   valgrind --tool=callgrind --toggle-collect=mobb_run_queries build/bench/mobb_query_driver fast 30 4096
// Only mobb_run_queries is measured (setup excluded); divide its instructions by N.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "workload.h"

extern "C" __attribute__((noinline)) std::size_t mobb_run_queries(const void* workload, int method, std::size_t n) {
    const auto& w = *static_cast<const mobb::bench::Workload*>(workload);
    std::size_t hits = 0;
    for (std::size_t i = 0; i < n; ++i) hits += w.query(mobb::bench::Method(method), i % w.size());
    return hits;
}

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: mobb_query_driver METHOD FPS N\n");
        return 2;
    }
    try {
        const mobb::bench::Method m = mobb::bench::parse_method(argv[1]);
        const double fps = std::atof(argv[2]);
        const auto n = std::size_t(std::atoll(argv[3]));
        const auto w = mobb::bench::Workload::make(fps, m == mobb::bench::Method::Fcl);
        if (m == mobb::bench::Method::Fcl && w.fcl.empty()) throw std::runtime_error("built without FCL");
        const std::size_t hits = mobb_run_queries(&w, int(m), n);
        // Agreement with the exact answer (fast query; the tests hold it to brute force), outside
        // the measured function: "extra" = this method says yes where the model says no.
        std::size_t extra = 0, missed = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const bool got = w.query(m, i % w.size()), exact = w.query(mobb::bench::Method::Fast, i % w.size());
            extra += got && !exact;
            missed += !got && exact;
        }
        std::printf("%s %g Hz (%s): %zu queries, %zu hits, %zu extra, %zu missed vs exact\n", argv[1], fps,
                    mobb::bench::source().c_str(), n, hits, extra, missed);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mobb_query_driver: %s\n", e.what());
        return 1;
    }
    return 0;
}
