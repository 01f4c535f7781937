// A choice point's queries against the walls and obstacles and the other agents' pieces, as its
// candidates, their plans and its rules ask them: every box asked of the broad phase is noted (so that the
// frame can tell which commits could change the evaluation: affected_by), and every query is counted in
// the choice point's record (ChoicePoint), for the candidate it tests where it tests one. Private to
// src/crowd.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "collision/batch_grid.h"
#include "mobb/crowd/record/record.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// What a candidate's queries do at a hit: stop, or go on and count them all (the fallback).
enum class Hits : std::uint8_t { Stop, Count };

/// A test of another agent's piece - its broad-phase id and the piece - that a query goes past or leaves
/// out (the right of way's reservations that may be rerouted, a follower's leaders): a callable taken by
/// reference, without a copy or an allocation, so it must outlive the call it is passed to. Empty, it
/// holds for no piece.
class PieceFilter {
public:
    PieceFilter() = default;
    template <class F>
    PieceFilter(const F& f)  // from a lambda as it is: bool(int id, const Piece& piece)
        : f_(&f), test_([](const void* g, int id, const Piece& p) { return (*static_cast<const F*>(g))(id, p); }) {}
    bool operator()(int id, const Piece& piece) const { return test_ != nullptr && test_(f_, id, piece); }

private:
    const void* f_ = nullptr;
    bool (*test_)(const void*, int, const Piece&) = nullptr;
};

class ChoiceQueries {
public:
    /// Forgets the last choice point's queries and record, keeping its candidates' memory (when the
    /// record left it); the queries from now on are agent `agent`'s at `frame`.
    void start(int agent, std::int64_t frame);

    /// The live pieces of agents other than the asker whose boxes overlap `box`, in the order they were
    /// placed (query_pieces); the box is noted. Valid until the next query.
    const std::vector<int>& pieces_near(const CrowdState& s, const SpaceTimeBox& box);
    /// Whether piece `mine` of candidate k's plan is free of the walls and obstacles, then of every live
    /// piece of the other agents; each query counts for candidate k (ChoicePoint::candidates[k]). A hit
    /// on another agent's piece that `passes` holds for (the right of way's reservations that may be rerouted)
    /// is gone past.
    bool candidate_free(const CrowdState& s, int k, const Piece& mine, Hits hits, PieceFilter passes = {});
    /// Whether a piece that is no candidate's (a searched step, a reroute's) is free of the walls and
    /// obstacles and of every live piece of agents other than its owner (piece.agent) but those `skip`
    /// holds for. Its queries count for the choice point, not for a candidate.
    bool piece_free(const CrowdState& s, const Piece& piece, PieceFilter skip = {});
    /// Whether two pieces collide (pieces_collide), the query counted for the choice point.
    bool collide(const CrowdState& s, const Piece& mine, const Piece& other);

    /// Whether a plan committed in the same frame by a choice point in [from, below) (batch positions)
    /// has a box in `chosen` that overlaps a box these queries asked about.
    bool affected_by(const BatchGrid& chosen, int from, int below) const;
    /// The last batch position before `below` whose plan's boxes in `chosen` overlap a box asked about
    /// (affected_by(chosen, that position, below) holds); -1 when none does.
    int last_change(const BatchGrid& chosen, int below) const;

    /// The record's choice point: its candidates and the counts of their queries.
    ChoicePoint& point() { return point_; }
    const ChoicePoint& point() const { return point_; }
    int queried() const { return int(queried_boxes_.size()); }
    /// The union of the boxes asked about (what affected_by() tests first); nothing when none was.
    std::optional<SpaceTimeBox> queried_bounds() const {
        if (queried_boxes_.empty()) return std::nullopt;
        return queried_all_;
    }
    std::uint64_t near_total() const { return near_total_; }
    std::uint64_t root_rejected() const { return root_rejected_; }
    /// The clip-against-clip queries in the order run, their choice left 0 (kept if log_queries).
    const std::vector<LoggedQuery>& log() const { return log_; }

private:
    void note(const SpaceTimeBox& box);
    void solids_near(const CrowdState& s, const SpaceTimeBox& box);
    bool free_of_solids(const CrowdState& s, int k, const Piece& mine, Hits hits);
    void count(const QueryStats& st);
    void record(const CrowdState& s, int k, const Piece& mine, CandidateQuery q, const QueryStats& st);

    int agent_ = 0;
    std::vector<int> near_;                    // scratch: broad-phase ids (or solid indices) of one query
    std::vector<SpaceTimeBox> queried_boxes_;  // every box asked of the broad phase
    SpaceTimeBox queried_all_;                 // their union (bounding box)
    bool solids_asked_ = false;                // solid_free_ is set for this choice point
    SpaceTimeBox solid_free_;                  // ground without solids (its time: all)
    std::uint64_t near_total_ = 0, root_rejected_ = 0;
    int last_hit_ = -1;  // broad-phase id of the other agent's piece that refused the last piece
    ChoicePoint point_;
    std::vector<LoggedQuery> log_;
};

}  // namespace mobb::crowd
