// The pose of agent K at time t: the one home for it, used by the viewer, `mobb export-crowd` and Python.
//
// An agent at global frame k plays one graph clip; its pose is the clip's source sample at that frame,
// moved into the world by the same rigid 2D motion that placed the clip's root path (source root at sample
// `first` to the origin, heading to +x, then the clip's placement). At a clip start the pose eases from
// where the previous clip left it (blending, below). Units: metres, seconds, radians.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/motion/foot_contact.h"
#include "mobb/crowd/record/record.h"
#include "mobb/crowd/record/record_file.h"

namespace mobb::crowd {

/// The graph file a record names (Record::graph), or the committed graph (default_graph_file) when the
/// record names it relative to the repository and the working directory is elsewhere.
std::string record_graph_file(const Record& record);

/// One graph source as the poses need it: the animation, per sample the root and heading the graph used
/// to localise clips (pose_track), the lowest joint height over the take (the skeleton's feet), and its
/// foot contacts (detect_contacts; empty tracks when the skeleton has no `L_Foot` / `L_ToeBase` ...).
struct PoseSource {
    std::shared_ptr<const io::Clip> clip;  ///< null when it could not be loaded (see error)
    std::vector<double> root_x, root_y, heading;
    double floor = 0.0;
    std::array<FootTrack, 2> feet;  ///< left, right
    std::string error;
};

/// Rigid motion from source ground coordinates to the world for graph clip `clip` placed at `place`
/// (t0 kept): world = place o (rotate by -heading[first], root[first] to the origin).
Placement source_to_world(const PoseSource& source, const GraphClip& clip, const Placement& place);

/// The clip agent `agent` plays at global frame k (record frame k covers [k dt, (k + 1) dt)).
struct AgentClipAt {
    const PlacedClip* placed = nullptr;
    int index = 0;   ///< in the agent's track.clips
    int sample = 0;  ///< sample index in the source (graph fps)
};
/// The clip agent `agent` plays at global frame `k` of the record. False outside the agent's clips (or for
/// an agent or clip id that does not exist).
bool agent_clip_at(const Record& r, const MotionGraph& g, int agent, std::int64_t k, AgentClipAt& out);

/// Every source of one graph, each loaded on first use and kept (a failure too, with its reason, so a
/// missing file is not retried every frame), with its foot contacts found once, on loading. Not thread-safe.
class PoseSources {
public:
    explicit PoseSources(std::shared_ptr<const MotionGraph> graph) : graph_(std::move(graph)) {}
    /// Graph source `source`, loaded on first use. Throws std::out_of_range for a source the graph lacks.
    const PoseSource& get(int source) {
        // Loaded already: no call (the foot lock asks for a clip's source several times a frame).
        if (std::size_t(source) < sources_.size() && sources_[std::size_t(source)])
            return *sources_[std::size_t(source)];
        return load(source);
    }
    /// The foot contacts of graph clip `clip` (clip_contacts; loads its source; empty when it cannot be).
    const std::vector<ContactSpan>& contacts(int clip);
    /// The first load failure met so far ("" when none).
    const std::string& error() const { return error_; }
    int loaded() const;
    const MotionGraph& graph() const { return *graph_; }

private:
    std::shared_ptr<const MotionGraph> graph_;
    const PoseSource& load(int source);
    std::vector<std::unique_ptr<PoseSource>> sources_;
    std::vector<std::vector<ContactSpan>> contacts_;  ///< per clip, filled as its source loads
    std::string error_;
};

/// The joints every pose of a crowd carries, the same for every agent whatever source it plays: joint 0
/// is the mocap root (each source's own root, the root of its path, named as the first source's), then in the first source's order the joints whose names
/// every source has (All: End Sites included), or only the graph's compared joints (Major: pelvis, legs,
/// spine, head, arms; pose_distance.h). A joint's parent is its nearest kept ancestor.
enum class RigJoints { All, Major };
struct Rig {
    std::vector<std::string> names;
    std::vector<int> parents;                     ///< -1 for joint 0
    std::vector<std::vector<int>> source_joints;  ///< [source][joint]: its index in that source's skeleton
    int size() const { return int(names.size()); }
};
/// Loads every source of the graph. Throws io::LoadError / GraphError for a source that cannot be loaded.
Rig crowd_rig(PoseSources& sources, RigJoints joints);

/// Blending at clip starts: inertialization in its offset form (D. Bollo, "Inertialization:
/// High-Performance Animation Transitions in Gears of War", GDC 2018). At the first frame of a clip the
/// difference d_j between the pose the previous clip would show then (its exit sample) and the new clip's
/// first pose, both relative to the root, is added to the new clip's pose and decays to zero over
/// `window` seconds: offset(s) = d_j (1 - 3 s^2 + 2 s^3), s = time since the clip start / window (Bollo
/// fits a quintic to the offset's velocity; this cubic starts at the offset and ends with zero slope).
/// The root is never blended, so the ground path is exactly the clip's. Bound: a joint whose ground
/// distance to the disk's centre (the root, or off it for disks centred on the body) exceeds e(k) = min
/// over the next `look_ahead` seconds of r(k') + pull_speed (t_k' - t_k) (at most the record's r(t_k)) is
/// pulled radially (height kept) onto that circle, so the disk r(t)
/// the collision answers used still holds every joint of the blended pose, and where a clip starts from a
/// smaller disk than the pose it eases out of, joints are drawn in over the frames before (at most
/// pull_speed) rather than at once.
struct PoseBlend {
    double window = 0.25;     ///< seconds; 0 = no blending (the raw clips, jumping at clip starts)
    double pull_speed = 1.5;  ///< metres per second
    double look_ahead = 0.5;  ///< seconds
};

/// A leg of the rig (rig joint indices, -1 where the rig lacks it): hip (`Thigh`), knee (`Calf`), ankle
/// (`Foot`), toe (`ToeBase`), and the rig's other joints that hang from it with the segment they follow
/// (1: thigh, 2: shin, 3: foot).
struct RigLeg {
    int hip = -1, knee = -1, ankle = -1, toe = -1;
    std::vector<std::pair<int, int>> hanging;
    bool complete() const { return hip >= 0 && knee >= 0 && ankle >= 0 && toe >= 0; }
};
/// The left (0) and right (1) legs of `rig`.
std::array<RigLeg, 2> rig_legs(const Rig& rig);

/// What foot locking did at one frame, per foot (left, right).
struct FeetAt {
    std::array<Plant, 2> plant{};  ///< the foot's contact at the frame, its clip's own (Free: none)
    /// The contact the lock holds: `plant`, or one carried through a blend from the clip before
    /// (FootLock::carry); `plant` where locking is off.
    std::array<Plant, 2> hold{};
    std::array<bool, 2> held{};  ///< the ankle had a target (in contact, pinned, or letting either go)
    /// Pinned in a blend with no contact (FootLock::pin), not letting the pin go.
    std::array<bool, 2> pinned{};
    std::array<double, 2> residual{};  ///< metres from the ankle to its target after the IK (and the disk)
    /// Metres the planted (or pinned) point was lifted or dragged at this frame, where the leg could not reach
    /// it or it left the disk (FootLock::reach, FootLock::lift); 0 while the hold holds (its glide aside).
    std::array<double, 2> dragged{};
};

/// Poses of a record's agents. Throws like crowd_rig on construction; GraphError when the record's dt is
/// not the graph's (frames would not be samples). Not thread-safe (sources load on first use).
///
/// Foot locking (`lock`, on by default; foot_contact.h, Kovar et al. 2002): while a foot is in contact
/// (its source's contacts, continued across back-to-back clips, and carried through the blend after a
/// clip start where the clip before ends planted and the new one has the foot up: carried_plant) its
/// planted point - the ankle while the heel is down, the toe while only the toe is - stays where it was
/// in the world when the contact began (where the planted point changes, the new one's place follows from
/// the old one's), gliding towards the clip's own planted point (FootLock::glide); the ankle's target is
/// that point plus the pose's own ankle offset from it, and two_joint_ik bends the leg to reach it (the
/// rig's joints below the hip follow their segments). After a contact the foot is let go over
/// FootLock::release; a foot low in a blend with no contact is pinned (FootLock::pin); a contact that begins
/// while either still holds the foot comes down where it is (held_before). The root and every other joint are not touched; the leg is held inside the disk
/// like blended joints (where that moves the ankle off its target, it shows as the residual).
class CrowdPoser {
public:
    CrowdPoser(const Record& record, std::shared_ptr<PoseSources> sources, RigJoints joints = RigJoints::All,
               PoseBlend blend = {}, FootLock lock = {});
    const Rig& rig() const { return rig_; }
    const Record& record() const { return record_; }
    /// The agents' disks from `window` (frames there; kept by the caller, null: the record's tracks) for
    /// a record read in parts (record_reader.h), whose tracks hold none: the bound below uses the disks
    /// of the frames ahead, so a pose near the window's end is bound by the frames the window has.
    void use_samples(const SampleWindow* window) { window_ = window; }
    PoseSources& sources() const { return *sources_; }
    const PoseBlend& blend() const { return blend_; }
    const FootLock& lock() const { return lock_; }
    const std::array<RigLeg, 2>& legs() const { return legs_; }
    /// Joint positions of agent `agent` at global frame k: world ground coordinates (x, y, h), metres, h
    /// above the source's lowest joint (so feet stand on h = 0); out[0] is the root's ground point: the
    /// clip's path point (x, y) on the record's track, h = 0 (sources root their skeletons at the hips or
    /// at the floor, so the root's own height is not kept).
    /// An agent past the end of its clips (it left the run) keeps its last pose. False for an agent or frame
    /// outside the record.
    bool pose(int agent, std::int64_t k, std::vector<glm::dvec3>& out);
    /// Both at once (one posing for the two): `out` as pose() gives it, `raw` the same frame unblended
    /// (as a poser with window 0 gives it).
    bool pose(int agent, std::int64_t k, std::vector<glm::dvec3>& out, std::vector<glm::dvec3>& raw);
    /// All three at once, and what the locking did (`feet`, may be null): `unlocked` is `out` before foot
    /// locking (as a poser with FootLock::on false gives it).
    bool pose(int agent, std::int64_t k, std::vector<glm::dvec3>& out, std::vector<glm::dvec3>& raw,
              std::vector<glm::dvec3>& unlocked, FeetAt* feet);
    /// At time t (seconds, 0 <= t <= frames * dt): linear between the poses of the frames around t, so a
    /// frame's own time gives that frame's pose.
    bool pose_at(int agent, double t, std::vector<glm::dvec3>& out);

private:
    /// Where frame k's joints are held (see PoseBlend): on the ground at most `radius` metres from the root
    /// moved by `offset`, the disk's centre less the root (zero where the disks are centred on the root).
    struct Envelope {
        double radius = 0;
        glm::dvec2 offset{0.0};
    };
    struct FootFree {
        glm::dvec3 hip{0.0}, knee{0.0}, ankle{0.0}, toe{0.0};
        glm::dvec3 root{0.0};
        Envelope disk;  ///< e(k): every joint held inside it
    };
    /// A hold followed frame by frame from its contact's start (contact_target): the planted point, the
    /// ankle's target and free position at `frame`. Kept per agent and foot, so consecutive frames (the
    /// export, the metrics, playback) go on from the last one instead of starting over; the same numbers
    /// either way.
    struct Hold {
        std::int64_t start = -1, frame = -1;
        Plant plant = Plant::Free;
        glm::dvec3 point{0.0}, target{0.0}, ankle{0.0};
        glm::dvec3 toe{0.0};   ///< where the held foot's toe is at `frame` (the release lets it go from there)
        glm::dvec3 from{0.0};  ///< the ground offset from the free pose it came down at (held_before)
        double dragged = 0;    ///< metres, at `frame`
    };
    /// A foot pinned in a blend (FootLock::pin), followed frame by frame from its clip's start like a Hold.
    struct Pin {
        const PlacedClip* placed = nullptr;  ///< the clip whose blend it is
        std::int64_t frame = -1;             ///< the last frame followed
        std::int64_t contact = -1;           ///< the last frame up to `frame` in a contact (-1: none near)
        std::int64_t freed = -1;             ///< the first frame after the pin (-1: none yet)
        bool pinned = false;                 ///< at `frame`
        bool holds = false;                  ///< pinned or let go at `frame`: the ankle is moved by `shift`
        double height = 0;                   ///< metres the ankle is held above the free pose's (a contact's)
        glm::dvec3 toe{0.0};                 ///< where the toe is pinned
        glm::dvec3 correction{0.0};          ///< the ankle's from the free pose at the last pinned frame
        glm::dvec3 shift{0.0};               ///< the ankle's target from the free pose at `frame`
        double dragged = 0;                  ///< metres the pinned point was lifted or dragged at `frame`
    };
    /// Source sample `sample` of the clip `at` names, placed as that clip (joint 0 on the floor), for rig
    /// joints `joints` (joint 0 among them; the others of `out` are left as they are).
    bool raw(const AgentClipAt& at, int sample, const std::vector<int>& joints, std::vector<glm::dvec3>& out);
    /// Clip `at` starts where the clip before it reached its exit (back to back), so its start is blended.
    bool blends_into(const AgentClipAt& at) const;
    /// The pose before foot locking (blended, held inside the disk), for `joints` only.
    bool free_pose(int agent, std::int64_t k, const std::vector<int>& joints, std::vector<glm::dvec3>& out,
                   std::vector<glm::dvec3>& raw_out);
    /// e(k) (see PoseBlend), its radius infinite where the agent has no disk at frame k.
    Envelope envelope(int agent, std::int64_t k) const;
    /// The disk's centre less the root at frame m (metres, ground), on frames the agent has a disk.
    glm::dvec2 centre_offset(int agent, std::int64_t m) const;
    void hold_inside(const std::vector<int>& joints, const Envelope& e, std::vector<glm::dvec3>& out) const;
    // Foot locking (foot_lock.cpp).
    /// The foot's contact at frame k: its clip's own, or with `carry` also one carried through a blend
    /// (carried_plant).
    Plant plant_at(int agent, std::int64_t k, int foot, bool carry);
    Plant plant_in(const AgentClipAt& at, std::int64_t k, int foot, bool carry);
    /// Frame k of clip `at` is in the blend after its start, the clip has the foot up from its first sample,
    /// and the clip before (back to back) had it planted at its last frame and at its exit (the pose the
    /// blend eases out of): the plant of that last frame, the contact going on; else Free.
    Plant carried_plant(const AgentClipAt& at, std::int64_t k, int foot);
    /// The plant carried into clip `at` through its blend (Free: none), kept for the clip last asked about.
    Plant carried_into(const AgentClipAt& at, int foot);
    /// Frame i of a clip is blended (PoseBlend::window).
    bool in_blend(std::int64_t i) const;
    /// FootLock::release in frames.
    int release_frames() const { return release_frames_; }
    /// True where frame k (the frame being posed) and the `frames` frames before it are free in its clip:
    /// no release to look for (one lookup instead of one per frame back).
    bool free_for(int agent, std::int64_t k, int foot, int frames);
    bool foot_free(int agent, std::int64_t k, int foot, FootFree& out);
    const Hold* contact_target(int agent, std::int64_t k, int foot, Plant plant, const FootFree* free);
    struct Segment {
        std::int64_t begin;
        Plant plant;
    };
    /// The runs of equal plant of the contact at frame k, from k back to its start (latest first).
    void contact_runs(int agent, std::int64_t k, int foot, std::vector<Segment>& runs);
    /// The hold of the contact at frame k, followed into `h` from the contact's start (or on from where h
    /// stands in it); `runs` is scratch. False where a pose is missing.
    bool follow_contact(int agent, std::int64_t k, int foot, const FootFree* free, std::vector<Segment>& runs, Hold& h);
    /// The hold of the contact at frame k (without moving the kept holds).
    bool hold_at(int agent, std::int64_t k, int foot, Hold& out);
    void follow(Hold& h, int agent, std::int64_t k, int foot, const FootFree& q, Plant plant, bool first);
    void hold_step(Hold& h, const FootFree& q, Plant plant, bool first, const glm::dvec3* own,
                   const glm::dvec3& from) const;
    void glide_towards(glm::dvec3& point, const glm::dvec3& own) const;
    bool own_point(const AgentClipAt& at, int foot, Plant plant, glm::dvec3& out);
    bool played_at(int agent, std::int64_t k, AgentClipAt& at) const;
    glm::dvec3 within_reach(const glm::dvec3& target, const FootFree& q) const;
    /// The ankle's shift from the free pose d frames into a release (1 <= d <= `release`) of a foot whose toe
    /// was held at `toe`, the ankle `correction` off the free pose's then.
    glm::dvec3 release_shift(const glm::dvec3& toe, const glm::dvec3& correction, int d, int release,
                             const FootFree& free) const;
    /// What the lock does with one ankle at one frame: its target, metres the planted or pinned point was
    /// lifted or dragged to it, and whether a pin holds it.
    struct AnkleTarget {
        glm::dvec3 at{0.0};
        double dragged = 0;
        bool pinned = false;
    };
    bool ankle_target(int agent, std::int64_t k, int foot, const FootFree& free, AnkleTarget& out);
    /// The ankle's target while letting go after a contact, or false.
    bool released(int agent, std::int64_t k, int foot, const FootFree& free, glm::dvec3& target);
    /// Pin `p` at frame k (k's clip's blend or the release after it), followed on or over from the clip's
    /// start (`free`, `plant`: frame k's free pose and contact, where known); whether it holds the foot there.
    bool pin_at(Pin& p, int agent, std::int64_t k, int foot, const FootFree* free, const Plant* plant);
    void start_pin(Pin& p, int agent, const PlacedClip* placed, int foot);
    void pin_step(Pin& p, int agent, std::int64_t m, int foot, const FootFree& q, Plant plant);
    /// m/s: how fast frame i of clip `placed` moves the foot's toe over the ground, as captured.
    double own_toe_speed(const PlacedClip* placed, std::int64_t i, int foot) const;
    /// Pin `p` holds the foot pinned at frame m (starting it where it starts).
    bool pins(Pin& p, int agent, std::int64_t m, int foot, const FootFree& q, Plant plant);
    /// The ground offset from the free pose at which a pin or a release holds the ankle at frame start - 1,
    /// where a contact begins at `start` (so it comes down where the foot is), or false.
    bool held_before(int agent, std::int64_t start, int foot, glm::dvec3& out);
    /// The ground offset from the free pose at which a pin (or its letting go) has the ankle at frame k.
    bool pin_offset(int agent, std::int64_t k, int foot, glm::dvec3& out);
    /// The kept pin at frame k (free pose and contact there given), or null where none holds the foot.
    const Pin* pin_target(int agent, std::int64_t k, int foot, const FootFree& free, Plant plant);
    void lock_feet(int agent, std::int64_t k, std::vector<glm::dvec3>& out, FeetAt* feet);

    const Record& record_;
    const SampleWindow* window_ = nullptr;
    std::shared_ptr<PoseSources> sources_;
    Rig rig_;
    PoseBlend blend_;
    FootLock lock_;
    std::array<RigLeg, 2> legs_;
    std::vector<int> all_;                        // every rig joint
    std::array<std::vector<int>, 2> leg_joints_;  // per leg, the joints bending moves (root first)
    std::array<std::vector<int>, 2> foot_;        // per foot: root, hip, knee, ankle, toe
    std::vector<std::array<Hold, 2>> holds_;      // per agent and foot
    std::vector<std::array<Pin, 2>> pins_;        // per agent and foot
    std::vector<ClipKind> kinds_;                 // per graph clip (FootLock::pin_shuffles)
    int release_frames_ = 0;                      // FootLock::release in frames
    std::int64_t blend_frames_ = 0;               // frames a clip start blends (in_blend): ceil(window / dt)
    Envelope disk_;                               // e(k) of the last free_pose (with blending)
    AgentClipAt posed_;                           // the clip of the frame pose() poses (agent -1: none)
    int posed_agent_ = -1;
    std::int64_t posed_frame_ = 0;
    std::vector<glm::dvec3> a_, b_, c_, d_, e_, u_;
    std::vector<Segment> segments_;
    struct CarryCache {
        const PlacedClip* placed = nullptr;
        Plant plant = Plant::Free;
    };
    std::array<CarryCache, 2> carry_;  // per foot: carried_into's last clip and answer
    struct PlacedCache {
        const PlacedClip* placed = nullptr;
        Rigid2 to_world;  // the clip's source samples into the world
    };
    PlacedCache own_;  // own_point's last clip
};

}  // namespace mobb::crowd
