#include "mobb/core/trace.h"

namespace mobb {

const char* to_string(TraceTest test) {
    switch (test) {
        case TraceTest::Time: return "time";
        case TraceTest::Box2: return "box2d";
        case TraceTest::Box3: return "box3d";
        case TraceTest::Descend: return "descend";
        case TraceTest::Samples: return "samples";
    }
    return "?";
}

const char* to_string(TraceOutcome outcome) {
    switch (outcome) {
        case TraceOutcome::NoTimeOverlap: return "no time overlap";
        case TraceOutcome::Separated: return "separated";
        case TraceOutcome::Overlap: return "overlap";
        case TraceOutcome::Miss: return "miss";
        case TraceOutcome::Hit: return "hit";
    }
    return "?";
}

}  // namespace mobb
