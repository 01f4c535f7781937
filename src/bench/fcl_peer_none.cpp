// Stand-in when FCL (Debian libfcl-dev) is not installed: the FCL rows are skipped.
#include <stdexcept>

#include "fcl_peer.h"

namespace mobb::bench {

struct FclClip::Impl {};

FclClip::FclClip(const Path&, int) { throw std::runtime_error("built without FCL (install libfcl-dev)"); }
FclClip::~FclClip() = default;
FclClip::FclClip(FclClip&&) noexcept = default;
FclClip& FclClip::operator=(FclClip&&) noexcept = default;
std::size_t FclClip::triangles() const { return 0; }
bool fcl_collide(const FclClip&, const Placement&, const FclClip&, const Placement&) { return false; }
bool fcl_available() { return false; }

}  // namespace mobb::bench
