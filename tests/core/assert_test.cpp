// MOBB_ASSERT (include/mobb/core/assert.h): on in the sanitizer and Debug builds, where a broken
// precondition aborts with the place and the condition; compiled out in Release, where its condition
// is never evaluated.
#include <gtest/gtest.h>

#include "mobb/core/assert.h"
#include "mobb/core/fit.h"

namespace mobb {
namespace {

TEST(Assert, ABrokenPreconditionStopsWithItsPlace) {
#if defined(MOBB_ASSERTS)
    Path path;
    path.dt = 1.0 / 30;
    path.samples = {{0, 0, 0.3}, {1, 0, 0.3}};
    EXPECT_DEATH(fit_obb2(path, 1, 1),
                 "fit.cpp:[0-9]+: .*fit_obb2.*: Assertion `first < end && end <= path.samples.size\\(\\)' failed");
#else
    GTEST_SKIP() << "asserts are off in this build (Release); the sanitizer build runs this";
#endif
}

TEST(Assert, OffItNeverEvaluatesItsCondition) {
    int evaluated = 0;
    MOBB_ASSERT(++evaluated > 0);
#if defined(MOBB_ASSERTS)
    EXPECT_EQ(evaluated, 1);
#else
    EXPECT_EQ(evaluated, 0);
#endif
}

}  // namespace
}  // namespace mobb
