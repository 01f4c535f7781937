#include "workload.h"

#include <stdexcept>

namespace mobb::bench {

namespace {
constexpr const char* kNames[kMethods] = {"mobb",  "umobb", "hybrid1", "hybrid2", "mobb1",
                                          "umobb1", "brute", "scan",    "fast",    "fcl"};
}

const char* to_string(Method m) { return kNames[int(m)]; }

Method parse_method(const std::string& name) {
    for (int m = 0; m < kMethods; ++m)
        if (name == kNames[m]) return Method(m);
    throw std::invalid_argument("unknown method '" + name + "'");
}

Workload Workload::make(double fps, bool fcl) {
    const Path& pa = sequence42(0, fps);
    const Path& pb = sequence42(1, fps);
    Workload w{pa, pb, {}, {}, ClipIndex::build(pa), ClipIndex::build(pb), {}, {}};
    for (int t = 0; t < 6; ++t) {
        w.trees_a.push_back(Tree::build(pa, {TreeType(t), 10}));
        w.trees_b.push_back(Tree::build(pb, {TreeType(t), 10}));
    }
    if (fcl && fcl_available()) {
        w.fcl.emplace_back(pa);
        w.fcl.emplace_back(pb);
    }
    w.places = random_placements(pa.duration(), kPlacements, 2);
    return w;
}

}  // namespace mobb::bench
