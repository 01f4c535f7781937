// What an agent reserves (paper section 5): the clip it plays, the clips that would stop it, the ground
// it then holds - each a piece in the broad phase, which the others' plans must keep clear of. Shared by
// the choice point (choice/) and its rules (rules/). Private to src/crowd.
#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/collision/broad_phase.h"

namespace mobb::crowd {

/// The frame that never comes: held ground lasts until then.
inline constexpr std::int64_t kForever = std::numeric_limits<std::int64_t>::max();

/// Ground an agent holds from frame `frame` on, for as long as it stands there: a disk of radius r.
struct Hold {
    double x = 0, y = 0, r = 0;
    std::int64_t frame = 0;
};

/// A graph clip at its place in the world, from global frame `frame` on, with its box (place_clip) and
/// its rotation m = Rigid2::of(place), computed once for every query it takes part in.
struct BoxedClip {
    int clip = 0;
    Placement place;
    std::int64_t frame = 0;
    SpaceTimeBox box;
    Rigid2 m;
};

/// What an agent reserves beyond the clip it plays: the clips that would stop it, then the held ground.
struct Plan {
    std::vector<BoxedClip> escape;
    std::optional<Hold> hold;
};

/// One thing in the broad phase, by id: a clip an agent committed to or reserved, or its held ground.
/// (Walls and obstacles never change: they have a grid of their own, CrowdState::solid_grid.)
struct Piece {
    enum Kind : std::uint8_t { Clip, Held } kind = Clip;
    int agent = -1;        ///< owner
    int choice = 0;        ///< the choice point (record order) whose plan holds it
    int index = 0;         ///< 0: the clip committed to; 1, 2, ...: its escape clips; -1: the held ground
    std::int64_t seq = 0;  ///< pieces placed before it have smaller ones (broad-phase ids are reused)
    BoxedClip clip;        ///< Clip
    Hold hold;             ///< Held
};

/// Another agent's plan that gives way to a choice point's (the right of way): what it reserves from now
/// on, and the boxes of the pieces it releases.
struct Reroute {
    int agent = 0;
    Plan plan;
    std::vector<SpaceTimeBox> released;
};

/// The space-time box of held ground: its disk's bounds from its first frame on, for good.
inline SpaceTimeBox hold_box(const Hold& h) { return {h.x - h.r, h.y - h.r, h.x + h.r, h.y + h.r, h.frame, kForever}; }

/// The space-time box a piece takes in the broad phase: its clip's, or its held ground's (hold_box).
inline SpaceTimeBox box_of(const Piece& p) { return p.kind == Piece::Held ? hold_box(p.hold) : p.clip.box; }

/// The pieces agent `agent` reserves for `plan` by choice point `choice`, in order - its escape clips
/// (index 1, 2, ...), then its held ground - each handed to `take`.
template <class Take>
void plan_pieces(int agent, int choice, const Plan& plan, Take&& take) {
    Piece p;
    p.agent = agent;
    p.choice = choice;
    for (std::size_t i = 0; i < plan.escape.size(); ++i) {
        p.index = int(i) + 1;
        p.clip = plan.escape[i];
        take(p);
    }
    if (!plan.hold) return;
    p.kind = Piece::Held;
    p.index = -1;
    p.hold = *plan.hold;
    take(p);
}

/// Whether two held disks come closer than `gap` metres beyond touching.
inline bool holds_meet(const Hold& a, const Hold& b, double gap = 0) {
    const double dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r + gap;
    return dx * dx + dy * dy < r * r;
}

}  // namespace mobb::crowd
