// The paper's timing experiment (section 5): any successor, taken at random whatever it collides with.
// The choice point still runs every candidate's queries, so the work is that of a crowd that checks.
#include "mobb/crowd/policy/policy.h"

namespace mobb::crowd {

namespace {

class RandomPolicy : public Policy {
public:
    Selection kind() const override { return Selection::Random; }
    bool avoids() const override { return false; }
    void order(const ChoiceSite&, std::vector<int>&) const override {}  // the stream's order
};

}  // namespace

std::unique_ptr<Policy> random_policy() { return std::make_unique<RandomPolicy>(); }

}  // namespace mobb::crowd
