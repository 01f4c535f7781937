// The record of a crowd run (`mobb crowd --record FILE`): where every agent is at every global frame,
// which clips it played, and what was decided at every choice point. The viewer draws it.
//
// JSON layout (units: metres, seconds, radians; frames are global, frame k starts at t = k * dt):
//   {
//     "format": "mobb crowd record", "version": 1,
//     "graph": FILE, "dt": s, "frames": F, "world": [W, H], "agents": N, "seed": K,
//     "tree": "mobb" | ..., "select": "avoid" | "random",
//     "summary": { see CrowdSummary in crowd.h },
//     "tracks": [ {                                   // one per agent, index = agent id
//        "clips": [ {"clip": id, "start": frame, "place": [x, y, theta, t0], "fallback": bool,
//                    "commit": n}, ... ],              // commit: global order of the choice
//        "samples": [ [t, x, y, r], ... ]             // F samples: the world disk at frames 0..F-1
//     }, ... ],
//     "choices": [ {"agent": a, "frame": k, "t": s, "taken": clip id, "fallback": bool,
//                   "queries": q, "tests2d": n, "tests3d": n, "samples": n, "pruned": n,
//                   "candidates": [ {"clip": id, "outside": bool, "queries": q, "hits": h,
//                                    "against": [ [agent, index, hit], ... ]}, ... ]}, ... ]
//   }
// A candidate's "hits" counts the committed clips it collides with; in avoid mode the queries of a
// candidate stop at its first hit unless every candidate failed (then all are counted for the fallback).
// "against" lists its queries in the order run: the other agent, the index of that agent's committed
// clip in its track's "clips", and the answer (0 or 1).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mobb/core/path.h"

namespace mobb::crowd {

/// A clip an agent committed to: graph clip id, first global frame, world placement (t0 = start * dt).
struct PlacedClip {
    int clip = 0;
    std::int64_t start = 0;
    Placement place;
    bool fallback = false;    ///< chosen although every candidate collided or left the world
    std::int64_t commit = 0;  ///< order of the choice point that committed it
};

/// One narrow-phase query of a candidate: against clip `index` of agent `agent`'s track.
struct CandidateQuery {
    int agent = 0;
    int index = 0;
    bool hit = false;
};

struct Candidate {
    int clip = 0;
    bool outside = false;                 ///< leaves the world: some root position is farther outside the rectangle
                                          ///< than the clip's start (0 when it starts inside)
    int queries = 0;                      ///< narrow-phase queries run for it
    int hits = 0;                         ///< committed clips it collides with (see the layout note)
    std::vector<CandidateQuery> against;  ///< its queries, in the order run
};

struct ChoicePoint {
    int agent = 0;
    std::int64_t frame = 0;
    std::vector<Candidate> candidates;  ///< in the order tested
    int taken = 0;                      ///< clip id
    bool fallback = false;
    std::uint64_t queries = 0, tests2d = 0, tests3d = 0, samples = 0;
    std::uint64_t pruned = 0;  ///< time-overlapping committed clips the broad phase skipped
};

/// One agent: its clips in time order and its disk at every global frame, [t, x, y, r].
struct AgentTrack {
    std::vector<PlacedClip> clips;
    std::vector<std::array<double, 4>> samples;
};

struct Record {
    std::string graph, tree, select;
    double dt = 1.0 / 30.0;
    std::int64_t frames = 0;
    double width = 0, height = 0;  ///< the world rectangle [0, W] x [0, H]
    std::uint64_t seed = 0;
    std::vector<AgentTrack> tracks;
    std::vector<ChoicePoint> choices;
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

/// JSON text of a record (see the layout above); `summary` is inserted as given.
std::string record_to_text(const Record& record, const std::string& summary_json);

/// Reads a record file. Throws std::runtime_error "FILE: ..." on any problem.
Record load_record(const std::string& file);

}  // namespace mobb::crowd
