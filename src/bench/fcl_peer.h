// FCL peer of the benchmarks (only the benchmark library links FCL): each clip as one fcl::BVHModel<OBBRSSd>
// built once, queried with fcl::collide under the placements' transforms and a boolean request.
#pragma once
#include <memory>

#include "mobb/core/path.h"

namespace mobb::bench {

/// A clip's space-time volume as a triangle mesh in (x, y, t): sample i is a right prism with
/// `sides` faces circumscribing its disk (vertex radius r / cos(pi / sides), so the disk is inside),
/// extruded over [i dt, (i + 1) dt], closed by its two caps. Conservative: FCL may report contacts
/// the exact model does not (prism corners, and intervals that only touch end to end count for FCL),
/// and, being a surface test, could miss one solid strictly inside another (not seen on real data).
class FclClip {
public:
    explicit FclClip(const Path& path, int sides = 8);
    ~FclClip();
    FclClip(FclClip&&) noexcept;
    FclClip& operator=(FclClip&&) noexcept;

    std::size_t triangles() const;

    /// fcl::collide with transforms (rotation theta about t, translation (x, y, t0)), boolean request
    /// (one contact, no contact data). True when FCL reports a contact.
    friend bool fcl_collide(const FclClip& a, const Placement& pa, const FclClip& b, const Placement& pb);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

bool fcl_collide(const FclClip& a, const Placement& pa, const FclClip& b, const Placement& pb);

/// False when the benchmarks were built without FCL (then FclClip's constructor throws).
bool fcl_available();

}  // namespace mobb::bench
