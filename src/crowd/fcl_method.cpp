// The FCL peer as a QueryMethod (bench/fcl_peer.h; bench/fcl_peer_none.cpp when built without FCL).
#include <exception>

#include "fcl_peer.h"
#include "mobb/crowd/query_methods.h"

namespace mobb::crowd {

namespace {

class FclMethod : public QueryMethod {
public:
    std::string name() const override { return "FCL"; }
    void prepare(const std::vector<Path>& clips) override {
        models_.clear();
        if (!bench::fcl_available()) return;
        models_.reserve(clips.size());
        for (const Path& p : clips) models_.emplace_back(p);
    }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats*) const override {
        return bench::fcl_collide(models_[std::size_t(a)], pa, models_[std::size_t(b)], pb);
    }
    bool slow() const override { return true; }
    std::string unavailable() const override {
        return bench::fcl_available() ? std::string() : "built without FCL (libfcl-dev not found at configure time)";
    }
    std::string note() const override {
        return "conservative model: 8-sided prisms circumscribing the disks, extruded over each sample's interval";
    }

private:
    std::vector<bench::FclClip> models_;
};

}  // namespace

std::unique_ptr<QueryMethod> fcl_method() { return std::make_unique<FclMethod>(); }
bool fcl_built() { return bench::fcl_available(); }

}  // namespace mobb::crowd
