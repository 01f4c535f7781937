// Foot contacts of the motion capture, found once per graph source, and the leg's two-joint IK that holds a
// planted foot where it came down (foot locking, agent_pose.h). Reference: L. Kovar, J. Schreiner and M.
// Gleicher, "Footskate Cleanup for Motion Capture Editing" (SCA 2002): footplants found in the motion, the
// planted point held in the world, the leg bent analytically to reach it, the adjustment blended out after
// the plant. Units: metres, seconds, radians.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mobb/crowd/graph/motion_graph.h"

namespace mobb::crowd {

/// How a foot stands at one sample. A foot's heel is its ankle joint (`Foot`), its toe the `ToeBase` joint.
enum class Plant : std::uint8_t {
    Free,  ///< neither down: the foot swings
    Heel,  ///< the heel is down (the toe may be too): the ankle is the planted point
    Toe,   ///< only the toe is down (heel off, or standing on the toes): the toe is the planted point
};

/// When a heel or toe is down (detect_contacts): close to its ground level and slow, with hysteresis - it
/// comes down below height_on moving slower than speed_on and lifts above height_off or faster than
/// speed_off, so a joint hovering at one threshold does not flicker. A joint's ground level is a low
/// quantile of its height over the take (the ankle stands some 8 cm above the floor, the toe 2 to 4 cm).
/// This is Kovar et al.'s criterion (a footplant is a foot near the ground and nearly still); the numbers
/// are chosen on the CMU walks, where a planted heel or toe stays within 1 cm of its ground level moving at
/// 0.02 to 0.12 m/s, and swings at more than 1 m/s: lifting at 0.2 m/s ends a contact as the heel or toe
/// starts to leave, before the leg behind is stretched (on the 12-agent test crowd, lifting at 0.6 m/s and 5
/// cm let the held foot be dragged 4.9 cm per frame at p99 during walk contacts, 0.2 m/s and 3 cm 0.7 cm).
/// Down below 3 cm and up above 4 cm (2 and 3 cm before FootLock's glides and lift) hold the frames where a
/// heel settles: walk clips skate in 8.8 / 8.4 / 8.6 % of GMD's contact steps on the 100-agent wander (9.0 /
/// 8.6 / 8.8 %; the raw clips 8.8 / 8.5 / 8.6 %), and over `mobb bench crowd`'s 63 runs 4 have walk clips'
/// planted slide p99 over 1 cm (9). Coming down at 0.2 m/s and lifting at 0.3 m/s as well took slow clips from
/// 10.3-10.4 to 8.7-8.9 % but dragged held feet in 32 of those runs, up to 8.8 cm a frame.
struct ContactRule {
    double height_on = 0.03;        ///< metres above the joint's ground level to come down
    double height_off = 0.04;       ///< metres above it to lift
    double speed_on = 0.1;          ///< metres per second (horizontal) to come down
    double speed_off = 0.2;         ///< metres per second to lift
    double ground_quantile = 0.05;  ///< the joint's ground level: this quantile of its height over the take
    double merge_gap = 0.2;         ///< seconds: a foot's contacts closer than this are one (a lock does not
                                    ///< restart while the previous one still releases: FootLock::release is
                                    ///< no longer)
    double min_contact = 0.1;       ///< seconds: shorter contacts are dropped (a toe brushing the floor)
};

/// One foot over a source's samples: its plant per sample, per sample the first sample of the run of
/// equal plants it is in (so the start of a contact is found without walking it), and the heel and toe
/// positions it was found from (source ground coordinates, metres; kept for foot locking's glide).
struct FootTrack {
    std::vector<Plant> plant;
    std::vector<int> run_begin;
    std::vector<glm::dvec3> heel, toe;
};

/// A contact as a clip has it: samples [first, last] of its source (inside the clip's [first, exit)),
/// foot 0 left, 1 right. A contact that goes on past the clip ends at the clip's end.
struct ContactSpan {
    int foot = 0;
    int first = 0, last = 0;
};

/// Contacts of one source: per foot (left, right) the track, from per sample heel (ankle) and toe positions
/// (x, y, h: ground coordinates, h up, metres) at spacing dt seconds. Every input vector has one entry per
/// sample.
std::array<FootTrack, 2> detect_contacts(const std::array<std::vector<glm::dvec3>, 2>& heel,
                                         const std::array<std::vector<glm::dvec3>, 2>& toe, double dt,
                                         const ContactRule& rule = {});

/// The contacts of graph clip `clip` (samples [first, exit) of its source), in order of first sample, left
/// foot first where two start together.
std::vector<ContactSpan> clip_contacts(const std::array<FootTrack, 2>& feet, const GraphClip& clip);

/// Foot locking (agent_pose.h): whether it is on; how far a held leg may stretch - the hip-to-ankle distance
/// at most `reach` of the leg's length (thigh + shin), or the free pose's own where that is more: a foot
/// held beyond is dragged along towards the hip (the root path is never changed, so where two clips
/// disagree on where a planted foot stands, it slides by what the leg cannot absorb); and how a lock lets
/// go at a contact's end - the toe goes from where the hold left it to where the free pose has it over
/// `release` seconds (smoothstep), as blending's offsets ease out; and a foot low in a blend with no
/// contact, pinned (`pin`).
struct FootLock {
    bool on = true;
    double reach = 0.98;  ///< of the leg's length: a walker's knee at heel strike is nearly straight
    /// Seconds; Kovar et al. blend the adjustment out over a few frames. As long as ContactRule::merge_gap,
    /// the shortest gap between a foot's contacts, so a release ends before the next contact begins (0.15
    /// s let go faster: on the 100-agent wander, seed 1, walk clips skated in 11.6 % of GMD's contact
    /// steps, 0.2 s 11.3 %).
    double release = 0.2;
    /// Hold a contact on through the blend after a clip start where the new clip has the foot up from its
    /// first frame but the clip before had it planted at its end: the blend eases out of a planted pose, so
    /// its foot stays low while the offset carries it towards the new clip's swing (it skated there).
    bool carry = true;
    /// The release moves the let-go foot in the world: its toe goes from where the hold left it to where the
    /// free pose has it (smoothstep over `release`), so a foot that the blend or the clip moves over the
    /// floor stays behind and catches up. Off, the correction decays against the free pose (Kovar et al.)
    /// and the foot slides with the pose. On the 100-agent wander, seeds 1-3, % of GMD's contact steps that
    /// skate, walk / slow clips: both this and `pin` off 8.9 / 8.5 / 8.7 and 11.1 / 11.2 / 11.3; this alone
    /// 8.2 / 7.8 / 8.0 and 9.8 / 9.9 / 9.9; `pin` alone 8.5 / 8.1 / 8.2 and 10.5 / 10.6 / 10.6; both 7.7 /
    /// 7.3 / 7.5 and 9.1 / 9.3 / 9.3 (the raw clips: 8.8 / 8.5 / 8.6 and 7.7 / 7.9 / 7.7; bench/results/feet.md).
    bool release_in_world = true;
    /// In the blend after a clip start, a foot in no contact whose toe the blended pose has below `toe_down`
    /// and the clip itself moves slower than `pin_speed` is pinned: where a contact that just ended held it,
    /// else where the toe came down (once per blend, not while a contact is let go). It is let go as after a
    /// contact once the toe lifts or speeds up, a contact begins or the blend ends: the blend's decaying
    /// offset would slide it over the floor (up to 6 times the offset per second). A contact that begins
    /// while a pin or a release holds the foot comes down where they left it: on the 100-agent wander, seed
    /// 1, the toe steps 4.5 cm at p99 in such a first frame, as before pins (4.6 cm); coming down where the
    /// free pose has the foot, 23 cm at p99 (pins at any speed, seed 2).
    bool pin = true;
    /// m/s: in a walk clip, a foot the clip itself moves faster than this (GMD's skating speed,
    /// FootContact::kSkateSpeed) is swinging or sliding as captured, not pinned. Pinned at any speed in walks
    /// too, a foot landing from a swing was held short of where it lands and then dragged by the leg: planted
    /// slide p99 up to 5.2 cm in the goal scenarios (0.5-3.1 cm).
    double pin_speed = 0.5;
    /// In clips that are not walks (slow: starting, stopping; in place: turning on the spot; idle) a low foot
    /// is pinned whatever speed the clip itself moves it at: there a foot the capture moves while its toe is
    /// down shuffles or pivots, it does not land from a swing, and a pin has no landing to drag. On the
    /// 100-agent wander, seeds 1-3, slow clips then skate in 6.5 / 6.5 / 6.6 % of GMD's contact steps (9.1 /
    /// 9.3 / 9.3 off; the raw clips 7.7 / 7.9 / 7.7), walk clips as off; planted slide p99 of slow clips 0.50
    /// / 0.75 / 0.61 cm (0.50 / 0.61 / 0.50 off). Pinning at any speed in walks as well dragged landing feet
    /// (above).
    bool pin_shuffles = true;
    /// Metres: a toe below this is on the floor (GMD's contact height, FootContact::kHeight).
    double toe_down = 0.05;
    /// m/s, on the ground; 0 holds the planted point still. While the clip played has the contact itself
    /// (not one carried through a blend), the held point moves towards where that clip has the planted point
    /// at most this fast, so a foot that came down where a blend's offset put it, up to 20-30 cm from the
    /// clip's own footprint, gets there during the contact instead of standing until the leg or the disk
    /// runs out and dragging it. 0.5 cm a frame at 30 Hz, under the mocap's own p99 planted slide (0.65 cm).
    /// With `lift` and `glide_height`: 0.05 m/s left feet 19 cm off at the disk's edge (planted slide p99
    /// 1.04 cm on the 100-agent wander), 0.1 m/s 0.33-0.50 cm, 0.15 m/s 0.50, 0.2 m/s 0.67, the skating
    /// share the same within 0.2 points (bench/results/feet.md).
    double glide = 0.15;
    /// m/s: the held point's height moves towards the clip's own as fast, so a foot the blend put down high
    /// comes to the floor and counts as planted again (GMD's 5 cm); a lower foot beyond the leg's reach is
    /// lifted (`lift`). 0 holds the height. At 0.3 and 1.0 m/s walk clips skated within 0.1 points of 0.5
    /// m/s, in-place clips 0.3 points less and 0.9 more.
    double glide_height = 0.5;
    /// Beyond the leg's reach the planted point first rises until the leg reaches it (median 0.7 cm, p99 4
    /// cm on the 100-agent wander), a heel coming up as the leg stretches, and is dragged along the ground
    /// only where rising cannot bring it within reach; off, it is dragged towards the hip: with the glides
    /// above, planted slide p99 1.59 cm on walk clips against 0.50 (100-agent wander), and walk clips
    /// skated 0.2 points more.
    bool lift = true;
};

/// The leg after the two-joint IK: the new knee and ankle, and how far the ankle ends from the target
/// (metres; 0 where the target is reachable).
struct LegSolve {
    glm::dvec3 knee{0.0}, ankle{0.0};
    double residual = 0;
};

/// Analytic two-joint IK: the hip stays, the thigh (hip to knee) and shin (knee to ankle) keep the lengths
/// they have in the pose, and the ankle goes to `target`. The knee bends in the plane through hip and
/// target that holds the pose's knee (its pole: the knee's offset from the hip-ankle line); a straight leg
/// has no pole, and bends towards `forward` (the foot's direction) instead. A target farther than the leg
/// reaches gets the leg straight towards it (residual: the shortfall); one nearer than |thigh - shin| the
/// leg folded towards it.
LegSolve two_joint_ik(const glm::dvec3& hip, const glm::dvec3& knee, const glm::dvec3& ankle, const glm::dvec3& target,
                      const glm::dvec3& forward);

}  // namespace mobb::crowd
