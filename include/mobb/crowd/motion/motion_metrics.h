// How a crowd's motion looks, from its poses (agent_pose.h) after the run: pops where clips join, and feet
// sliding on the ground. Needs the graph's motion capture; the collision metrics (metrics.h) do not.
// Units: metres, seconds.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mobb/crowd/motion/agent_pose.h"

namespace mobb::crowd {

/// Median and p99 (the value 99 % of the sample do not exceed) of a sample, and its size.
struct Spread {
    double median = 0, p99 = 0;
    std::size_t count = 0;
};
/// Spread of `v` (reordered); zeros when empty.
Spread spread_of(std::vector<double>& v);

/// Foot contact and foot skating as GMD defines them for its foot skating ratio (K. Karunratanakul et al.,
/// "Guided Motion Diffusion for Controllable Human Motion Synthesis", ICCV 2023, section 5; also used by
/// OmniControl and later motion-synthesis evaluations): a foot (the toe joint) is in contact while it is
/// less than 5 cm above the ground, and it skates where it moves more than 2.5 cm in one frame of their
/// 20 fps data while in contact - 0.5 m/s horizontally. Footskate itself is Kovar, Schreiner and Gleicher's
/// term ("Footskate Cleanup for Motion Capture Editing", SCA 2002): a planted foot should not move.
struct FootContact {
    static constexpr double kHeight = 0.05;         ///< metres above the ground (h of the pose)
    static constexpr double kSkateSpeed = 0.5;      ///< metres per second, horizontal: 0.025 m x 20 fps
    static constexpr const char* kToe = "ToeBase";  ///< the joint taken as the foot, as GMD takes SMPL's foot joints
};

/// Feet while agents play clips of one kind: per foot and frame step (k - 1 to k, the clip of frame k),
/// counted where the foot is in contact at both frames.
struct FootSliding {
    std::size_t steps = 0;    ///< foot frame steps played with clips of this kind
    std::size_t contact = 0;  ///< of them, in contact at both ends
    Spread speed;             ///< horizontal speed in contact, m/s
    double skate_share = 0;   ///< contact steps faster than FootContact::kSkateSpeed / contact steps
};

/// Planted feet while agents play clips of one kind, by the contacts found in the motion capture
/// (foot_contact.h), not by GMD's rule: how the planted point (the ankle while the heel is down, the toe
/// while only the toe is) moves between consecutive frames of one contact, and how far the locked leg's
/// ankle ends from its target.
struct FootHold {
    Spread slide;     ///< metres per frame, horizontal; per foot and frame step inside a contact
    Spread residual;  ///< metres, ankle to target; per foot and frame with a target (locked poses only)
};

/// Pops and foot sliding of a crowd's poses. Joint jump: per agent and frame k >= 1 the largest move of a
/// joint relative to the root between frames k - 1 and k (metres), split into frames where a clip starts
/// and frames within clips (frames after an agent's clips end - it left - are not counted).
struct MotionMetrics {
    int joints = 0;       ///< per pose, root included
    double blend = 0;     ///< the blending window (PoseBlend::window), seconds; 0: the raw clips
    bool locked = false;  ///< feet locked (FootLock::on)
    Spread jump_start, jump_within;
    std::array<FootSliding, 4> sliding;  ///< by ClipKind (Walk, Slow, InPlace, Idle)
    std::array<FootHold, 4> hold;        ///< by ClipKind
    /// Knee pops: per agent and frame the largest change of a knee's angle (between thigh and shin) from
    /// frame k - 1 to k, radians, at clip starts and within clips as the joint jump.
    Spread knee_start, knee_within;
    bool feet = false;  ///< the rig has both legs (else sliding, hold and knees are empty)
    double jump_ratio() const { return jump_within.p99 > 0 ? jump_start.p99 / jump_within.p99 : 0.0; }
    double knee_ratio() const { return knee_within.p99 > 0 ? knee_start.p99 / knee_within.p99 : 0.0; }
};

/// A crowd's motion as everything shows it (`blended`: blending and, when the poser locks feet, foot
/// locking), blended without foot locking, and the raw clips.
struct CrowdMotion {
    MotionMetrics blended, unlocked, raw;
    double seconds = 0;  ///< wall time to measure them (sources loading included by crowd_motion)
};

/// All three, of `agents` over global frames [frame_begin, frame_end), in one posing: `blended` with the
/// poser's blending and locking, `unlocked` without the locking, `raw` the same frames unblended. `threads` workers each pose their own agents (the
/// sources are loaded once, by the poser's construction).
CrowdMotion motion_metrics(CrowdPoser& poser, const std::vector<int>& agents, std::int64_t frame_begin,
                           std::int64_t frame_end, int threads = 1);

/// Every agent and frame of `record`, all joints, blending window `blend` (seconds), feet locked or not.
/// Throws like CrowdPoser (io::LoadError without the motion capture, GraphError).
CrowdMotion crowd_motion(const Record& record, std::shared_ptr<const MotionGraph> graph,
                         double blend = PoseBlend{}.window, int threads = 1, bool lock_feet = FootLock{}.on);

/// As a JSON object (the record's metrics "motion") and as `mobb crowd` prints it.
std::string motion_json(const CrowdMotion& m);
std::string motion_text(const CrowdMotion& m);
/// `metrics_json` (a JSON object) with "motion": `motion_json` added.
std::string with_motion(const std::string& metrics_json, const CrowdMotion& m);

}  // namespace mobb::crowd
