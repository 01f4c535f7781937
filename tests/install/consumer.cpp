// Two walkers crossing: collide at the same time, miss when one starts after the other ends.
#include <cstdio>

#include "mobb/core/query.h"

int main() {
    mobb::Path walk;
    for (int i = 0; i < 120; ++i) walk.samples.push_back({0.02 * i, 0.0, 0.3});
    const mobb::Tree tree = mobb::Tree::build(walk);
    const bool same_time = mobb::collide(tree, {0, 0, 0, 0}, tree, {1.2, -1.2, 1.5707963, 0});
    const bool later = mobb::collide(tree, {0, 0, 0, 0}, tree, {1.2, -1.2, 1.5707963, 2.5});
    std::printf("same time: %d, later: %d\n", same_time, later);
    return same_time && !later ? 0 : 1;
}
