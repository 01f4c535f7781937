// The record of a crowd run (`mobb crowd --record FILE`): the world, where every agent is at every
// global frame, which clips it played, and what was decided at every choice point. The viewer draws it.
//
// JSON layout (units: metres, seconds, radians; frames are global, frame k starts at t = k * dt):
//   {
//     "format": "mobb crowd record", "version": 3,
//     "graph": FILE, "dt": s, "frames": F, "agents": N, "seed": K, "tree": "sweep" | "mobb" | ...,
//     "select": "wander" | "random" | "goal" ("avoid" before issue 44), "scenario": NAME (when one ran),
//     "world": [W, H] for [0, W] x [0, H], or [x0, y0, x1, y1]; "walls": bool,
//     "obstacles": [ [[x, y], ...], ... ],            // polygons
//     "summary": { see CrowdSummary in crowd.h }, "metrics": { see metrics.h },
//     "tracks": [ {                                   // one per agent, index = agent id
//        "goal": [x, y] (goal agents with one goal), or "goals": [[x, y], ...] (a sequence, reached in
//        turn), "at_goal": "leave" (when it leaves at its last goal; else it stays), "left_frame": f (the
//        frame it left at: its samples stop before it),
//        "clips": [ {"clip": id, "start": frame, "place": [x, y, theta, t0], "fallback": bool,
//                    "choice": n}, ... ],              // choice: the choice point that took it (-1: none)
//        "samples": [ [t, x, y, r], ... ]             // the world disk at frames 0..F-1 (0..left_frame-1)
//     }, ... ],
//     "choices": [ {"agent": a, "frame": k, "t": s, "taken": clip id, "outcome": "candidate" | "escape" |
//                   "arrived" | "fallback" | "right of way", "fallback": bool, "queries": q, "tests2d": n,
//                   "tests3d": n, "samples": n, "pruned": n,
//                   "plan": {"escape": [[clip, frame, x, y, theta], ...], "hold": [x, y, r, frame],
//                            "reroutes": [ {"agent": b, "escape": [...], "hold": [...]}, ... ]},
//                   "candidates": [ {"clip": id, "leaves_world": bool, "meets_solid": bool, "queries": q,
//                                    "hits": h, "against": [ [agent, index, piece, mine, hit], ... ],
//                                    "crowded": true (when so)}, ... ]}, ... ]
//   }
// A candidate's "hits" counts what it collides with among the queries run: in the avoiding modes its
// queries stop at its first hit (and run in full at a fallback); in random mode they all run. "against"
// lists its queries in the order run: the other agent, the index of what it met - for an agent the
// choice point whose plan holds the piece met (its index in "choices"; -1 for the ground it held where
// it started, a disk of the first choice point's hold radius) - and the piece (0 its clip, 1, 2, ... its
// escape clips, -1 its held ground), the piece of the candidate's own plan that asked ("mine": 0 the
// candidate clip, 1, 2, ... the escape clips of the route being tried, -1 the ground it would then hold)
// and the answer (0 or 1); for a wall or an obstacle the agent is -1, the index the solid's (the
// obstacles in order, then the four walls when walled) and the piece 0. "leaves_world" (random mode only):
// the candidate's root goes farther outside the world rectangle than where it starts. "meets_solid": one
// of its queries met a wall or an obstacle. Version 2 records (clips' "commit", candidates' one flag
// "outside") still read (formats.md). "reroutes" (only at a "right of way"
// choice point) are the plans other agents reserve from then on instead of theirs: their pieces are
// named by that choice point's index and their own agent. "crowded": refused, and some of its routes
// were left out untested because they would hold ground within the standing gap of another agent's (a
// wandering agent's preference, CrowdTuning::standing_gap in tuning.h, not a collision): a refused candidate
// without hits was refused for that alone.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/world/world.h"

namespace mobb::crowd {

/// A clip an agent committed to: graph clip id, first global frame, world placement (t0 = start * dt).
struct PlacedClip {
    int clip = 0;
    std::int64_t start = 0;
    Placement place;
    bool fallback = false;    ///< chosen although every candidate collided or left the world
    std::int64_t choice = 0;  ///< index of the choice point that took it (-1: the agent's first clip)
};

/// The version of the record layout written (record_json_write.cpp, record_h5_write.cpp).
constexpr int kRecordVersion = 3;

/// One narrow-phase query of a candidate: piece `mine` of the candidate's plan against piece `piece` of
/// the plan of choice point `choice`, agent `agent`'s (the layout note says which piece is which), or,
/// agent -1, against wall or obstacle `solid`.
struct CandidateQuery {
    int agent = 0;
    int choice = -1;  ///< agent >= 0: the choice point whose plan holds the piece (-1: its starting ground)
    int solid = -1;   ///< agent -1: the solid's index (the obstacles, then the four walls when walled)
    int piece = 0;
    int mine = 0;  ///< 0: the candidate clip; 1, 2, ...: the escape clips of the route tried; -1: its held ground
    bool hit = false;
};

/// What a query names at position 1 of the record's [agent, index, piece, mine, hit]: the choice point
/// (agent >= 0) or the solid (agent -1).
inline int query_index(const CandidateQuery& q) { return q.agent < 0 ? q.solid : q.choice; }

struct Candidate {
    int clip = 0;
    bool leaves_world = false;            ///< random mode only: some root position is farther outside the
                                          ///< world rectangle than the clip's start
    bool meets_solid = false;             ///< one of its queries met a wall or an obstacle (avoiding modes)
    int queries = 0;                      ///< narrow-phase queries run for it
    int hits = 0;                         ///< what it collides with among them (see the layout note)
    std::vector<CandidateQuery> against;  ///< its queries, in the order run
    bool crowded = false;                 ///< refused, routes left out for the standing gap (layout note)
};

/// A clip placed in the world from global frame `frame` on.
struct FramedClip {
    int clip = 0;
    std::int64_t frame = 0;
    Placement place;
};

/// Another agent's plan that gave way to a choice point's (the right of way, crowd.h): from then on it
/// reserves these clips to stop with and this ground instead of what it reserved before.
struct ReroutedPlan {
    int agent = 0;
    std::vector<FramedClip> escape;
    std::array<double, 3> hold{};  ///< x, y, r (metres)
    std::int64_t hold_frame = 0;
};

struct ChoicePoint {
    int agent = 0;
    std::int64_t frame = 0;
    std::vector<Candidate> candidates;  ///< in the order tested
    int taken = 0;                      ///< clip id
    std::string outcome = "candidate";  ///< "candidate", "escape", "arrived", "fallback" or "right of way"
    bool fallback = false;
    std::uint64_t queries = 0, tests2d = 0, tests3d = 0, samples = 0;
    std::uint64_t pruned = 0;            ///< time-overlapping committed pieces the broad phase skipped
    std::vector<FramedClip> escape;      ///< reserved after the clip taken: the clips that would stop the agent,
    bool holds = false;                  ///< then the held ground:
    std::array<double, 3> hold{};        ///< x, y, r (metres)
    std::int64_t hold_frame = 0;         ///< from this frame on
    std::vector<ReroutedPlan> reroutes;  ///< the other agents' plans that gave way ("right of way")
    /// The clips the look-ahead intends after the one taken (goal agents, src/crowd/rules/look_ahead.h): the
    /// rest of the sequence that ranked the taken clip first, re-planned at the next choice point. Not
    /// reserved: the escape is what the others plan around.
    std::vector<FramedClip> intended;
};

/// What a goal agent does at its last goal (SteerSuite's semantics for "leave"): stand there to the end
/// of the run, or leave the run - an exit, a door - its track ending there and holding no ground after.
enum class AtGoal : std::uint8_t { Stay, Leave };
const char* to_string(AtGoal at_goal);
/// "stay" or "leave"; nothing for anything else.
std::optional<AtGoal> at_goal_of(const std::string& name);

/// One agent: its clips in time order and its disk at every global frame it is in the run, [t, x, y, r]:
/// frames 0 .. frames - 1, or 0 .. left_frame - 1 for one that left.
struct AgentTrack {
    std::vector<PlacedClip> clips;
    std::vector<std::array<double, 4>> samples;
    std::vector<std::array<double, 2>> goals;  ///< metres, reached in turn (goal agents; empty: it wanders)
    AtGoal at_goal = AtGoal::Stay;
    std::optional<std::int64_t> left_frame;  ///< the frame it left the run at (AtGoal::Leave, once there)
};

struct Record {
    std::string graph, tree, select, scenario;
    double dt = 1.0 / 30.0;
    std::int64_t frames = 0;
    World world;
    std::uint64_t seed = 0;
    std::vector<AgentTrack> tracks;
    std::vector<ChoicePoint> choices;
};

/// Frames first .. first + count - 1 of a run, once final (every agent's committed clips cover them):
/// every agent's disk then, frame-major.
struct FrameBlock {
    std::int64_t first = 0, count = 0;
    std::size_t agents = 0;
    /// count x agents disks [t, x, y, r] (seconds, metres): agent a at frame first + k is
    /// disks[k * agents + a]; NaN from the frame it left the run on.
    const std::array<double, 4>* disks = nullptr;
};

/// Where a run streams its record (CrowdOptions::sink): a record file written as the run goes
/// (record_file.h). Called from the simulation's thread: begin() first, then choice points and clips in
/// commit order (a choice point's index is its place in Record::choices) and frame blocks in frame order,
/// as they come. The base takes them and keeps nothing: a run that needs only its summary and metrics.
class RecordSink {
public:
    virtual ~RecordSink() = default;
    /// Whether choice() and clip() keep what they get: a run skips those calls to a sink that does not
    /// (the base), as they are made in commit order, on one thread.
    virtual bool keeps_commits() const { return false; }
    /// The run's header (dt, frames, world, seed, ...) and its tracks' goals and at_goal, before frame 0.
    virtual void begin(const Record& /*header*/) {}
    virtual void choice(std::size_t /*index*/, const ChoicePoint& /*choice*/) {}
    /// A clip agent `agent` committed (PlacedClip::choice names its choice point).
    virtual void clip(int /*agent*/, const PlacedClip& /*clip*/) {}
    virtual void frames(const FrameBlock& /*block*/) {}
};

/// Two agents' disks overlapping at one global frame: |p_a - p_b| < r_a + r_b (the core's sample test).
struct Contact {
    std::int64_t frame = 0;
    int a = 0, b = 0;      ///< a < b
    bool excused = false;  ///< either agent was playing a fallback clip then
};

/// Every contact in the record, checked frame by frame on the samples (a uniform grid per frame),
/// independently of the trees. Ordered by frame, then a, then b.
std::vector<Contact> frame_contacts(const Record& record);

/// The clip a query was against: piece `piece` of choice point `choice`'s plan (the clip taken, or one of
/// its escape clips; for another agent than the choice point's, one of the escape clips of its reroute);
/// nothing for held ground and solids. Throws std::out_of_range for a bad query.
std::optional<FramedClip> query_clip(const Record& record, const CandidateQuery& query);
/// The same for a record whose choice points are read one at a time (record_reader.h): `named` is the
/// choice point the query names (query.choice), needed for its escape clips (piece > 0) only; the
/// record's tracks give the clips taken. Throws std::out_of_range for a bad query or a needed `named`
/// that is null.
std::optional<FramedClip> query_clip(const Record& record, const CandidateQuery& query, const ChoicePoint* named);

/// Held ground: the disk x, y, r (metres) an agent keeps from global frame `frame` on.
struct HeldGround {
    std::array<double, 3> disk{};
    std::int64_t frame = 0;
};
/// The held ground a query was against (piece -1): that of choice point `choice`'s plan, or of its
/// reroute for another agent; nothing for the ground an agent started on (choice -1), clips and solids.
/// Throws std::out_of_range for a bad query.
std::optional<HeldGround> query_hold(const Record& record, const CandidateQuery& query);

/// JSON text of a record (see the layout above); `summary` and `metrics` (JSON objects) are inserted as
/// given.
std::string record_to_text(const Record& record, const std::string& summary_json, const std::string& metrics_json = "");

/// Reads a record file. Throws std::runtime_error "FILE: PLACE: message" (one line, PLACE like
/// tracks[2].samples[7][3]) on any problem. Every field is checked against what it means: dt a frame of a
/// graph (1 / kMaxGraphFps to 1 / kMinGraphFps s), frames >= 1, positions within 1000 km and radii in
/// [0, 10] m, a world of positive area, obstacles of two or more vertices, "agents" the tracks' count; per
/// track clips in time order from frame 0 (start < frames, t0 = start * dt, choice points in order, each
/// -1 or an index in choices), one sample [t, x, y, r] per frame with t = k * dt; per choice point an
/// agent and a frame of the record (t = frame * dt), a known outcome, counts not negative,
/// finite escape places and held ground (r >= 0), reroutes of existing agents, candidates with
/// 0 <= hits <= queries and no more queries listed than run, each naming a wall or obstacle of the world, an
/// agent's starting ground or an earlier choice point. Clip ids are checked against a graph by
/// check_graph_clips. An incomplete HDF5 record (record_file.h) is read up to its last mark, its note
/// printed on stderr.
Record load_record(const std::string& file);

/// Throws std::runtime_error "PLACE: clip N is not in the graph GRAPH (M clips)" for the first clip id of the
/// record (a track's clip, a choice point's taken, candidate or escape clip) that a graph of `clips` clips
/// lacks.
void check_graph_clips(const Record& record, std::size_t clips);

}  // namespace mobb::crowd
