// Runs N queries of one method on one of issue 5's workloads (crowd_workload.h), for instruction counts:
//   valgrind --tool=callgrind --toggle-collect=mobb_run_clip_queries build/bench/mobb_crowd_driver crowd fast 0
// Only mobb_run_clip_queries is measured (setup excluded); divide its instructions by N (0 = every
// query of the workload once). bench/crowd_callgrind.sh does it for every method.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "crowd_workload.h"

extern "C" __attribute__((noinline)) std::size_t mobb_run_clip_queries(const void* workload, int method, std::size_t n) {
    const auto& w = *static_cast<const mobb::bench::ClipWorkload*>(workload);
    std::size_t hits = 0;
    for (std::size_t i = 0; i < n; ++i) hits += w.query(mobb::bench::CrowdMethod(method), i % w.size());
    return hits;
}

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: mobb_crowd_driver crowd|longest|synth42|synth120 fast|scan|mobb1|mobb N\n");
        return 2;
    }
    try {
        const mobb::bench::CrowdMethod m = mobb::bench::parse_crowd_method(argv[2]);
        const auto w = mobb::bench::ClipWorkload::make(argv[1]);
        std::size_t n = std::size_t(std::atoll(argv[3]));
        if (n == 0) n = w.size();
        const std::size_t hits = mobb_run_clip_queries(&w, int(m), n);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < n; ++i)
            wrong += w.query(m, i % w.size()) != w.query(mobb::bench::CrowdMethod::Mobb1, i % w.size());
        std::printf("%s %s (%s): %zu queries, %zu hits, %zu differ from mobb1\n", argv[1], argv[2], w.description.c_str(),
                    n, hits, wrong);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mobb_crowd_driver: %s\n", e.what());
        return 1;
    }
    return 0;
}
