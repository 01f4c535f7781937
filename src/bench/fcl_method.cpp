// The FCL peer as a QueryMethod (fcl_peer.h; fcl_peer_none.cpp when built without FCL).
#include <exception>

#include "fcl_peer.h"
#include "method.h"

namespace mobb::bench {

namespace {

class FclMethod : public QueryMethod {
public:
    Method method() const override { return Method::Fcl; }
    void prepare(const std::vector<Path>& clips) override {
        models_.clear();
        if (!fcl_available()) return;
        models_.reserve(clips.size());
        for (const Path& p : clips) models_.emplace_back(p);
    }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats*) const override {
        return fcl_collide(models_[std::size_t(a)], pa, models_[std::size_t(b)], pb);
    }
    bool slow() const override { return true; }
    std::string unavailable() const override {
        return fcl_available() ? std::string() : "built without FCL (libfcl-dev not found at configure time)";
    }
    std::string note() const override {
        return "conservative model: 8-sided prisms circumscribing the disks, extruded over each sample's interval";
    }

private:
    std::vector<FclClip> models_;
};

}  // namespace

std::unique_ptr<QueryMethod> fcl_method() { return std::make_unique<FclMethod>(); }

}  // namespace mobb::bench
