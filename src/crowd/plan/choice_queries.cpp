#include "plan/choice_queries.h"

#include <algorithm>
#include <limits>

namespace mobb::crowd {

namespace {

// What a piece's solid queries cover: its held ground reaches as far as it keeps clear of the walls.
SpaceTimeBox solid_box(const CrowdState& s, const Piece& p) {
    const Hold& h = p.hold;
    return p.kind == Piece::Held ? hold_box({h.x, h.y, std::max(h.r, s.hold_clearance), h.frame}) : p.clip.box;
}

}  // namespace

void ChoiceQueries::start(int agent, std::int64_t frame) {
    std::vector<Candidate> candidates = std::move(point_.candidates);
    candidates.clear();
    point_ = ChoicePoint{};
    point_.candidates = std::move(candidates);
    point_.agent = agent;
    point_.frame = frame;
    agent_ = agent;
    queried_boxes_.clear();
    solids_asked_ = false;
    near_total_ = 0;
    root_rejected_ = 0;
    last_hit_ = -1;
    log_.clear();
}

void ChoiceQueries::note(const SpaceTimeBox& b) {
    if (queried_boxes_.empty()) queried_all_ = b;
    queried_all_.enclose(b);
    queried_boxes_.push_back(b);
}

const std::vector<int>& ChoiceQueries::pieces_near(const CrowdState& s, const SpaceTimeBox& box) {
    note(box);
    query_pieces(s, box, agent_, near_);
    return near_;
}

void ChoiceQueries::count(const QueryStats& st) {
    ++point_.queries;
    point_.tests2d += st.tests2d;
    point_.tests3d += st.tests3d;
    point_.samples += st.samples;
}

void ChoiceQueries::record(const CrowdState& s, int k, const Piece& mine, CandidateQuery q, const QueryStats& st) {
    Candidate& cand = point_.candidates[std::size_t(k)];
    ++cand.queries;
    count(st);
    if (q.hit) ++cand.hits;
    if (!s.options.record_queries) return;
    q.mine = mine.index;
    cand.against.push_back(q);
}

// The solids whose bounds overlap `box`, by solid index, into near_ (solid_grid.query). Walls and
// obstacles never change: where one query around the choice point's first box finds none, every box
// of the evaluation on that ground has none near.
void ChoiceQueries::solids_near(const CrowdState& s, const SpaceTimeBox& box) {
    // Metres: most candidates and their plans stay this close. A bound on the work, not a choice: the
    // answers are the same for any value.
    constexpr double kAround = 6.0;
    constexpr auto kAll = std::numeric_limits<std::int64_t>::max();
    if (!solids_asked_) {
        solids_asked_ = true;
        const SpaceTimeBox around{box.x0 - kAround, box.y0 - kAround, box.x1 + kAround, box.y1 + kAround, -kAll, kAll};
        s.solid_grid.query(around, -2, near_);
        solid_free_ = near_.empty() ? around : SpaceTimeBox{0, 0, -1, -1, 0, 0};
    }
    const SpaceTimeBox& f = solid_free_;
    if (f.x0 <= box.x0 && box.x1 <= f.x1 && f.y0 <= box.y0 && box.y1 <= f.y1) return near_.clear();
    s.solid_grid.query(box, -2, near_);
}

// The walls and obstacles near the piece (held ground reaches as far as it keeps clear of them), by
// solid index; tested first: they stop most plans that fail near a wall, without an agent query. None
// is ever rerouted.
bool ChoiceQueries::free_of_solids(const CrowdState& s, int k, const Piece& mine, Hits hits) {
    solids_near(s, solid_box(s, mine));
    bool free = true;
    for (int i : near_) {
        const bool hit = meets_solid(s, mine, i);
        CandidateQuery q;
        q.agent = -1, q.solid = i, q.hit = hit;
        record(s, k, mine, q, {});
        if (!hit) continue;
        point_.candidates[std::size_t(k)].meets_solid = true;
        free = false;
        if (hits != Hits::Count) return false;
    }
    return free;
}

// The queries of one piece of candidate k's plan: the solids, then every other agent's piece live in
// the broad phase.
bool ChoiceQueries::candidate_free(const CrowdState& s, int k, const Piece& mine, Hits hits, PieceFilter passes) {
    bool free = free_of_solids(s, k, mine, hits);
    if (!free && hits != Hits::Count) return false;
    const SpaceTimeBox box = box_of(mine);
    note(box);
    query_pieces(s, box, agent_, near_);
    near_total_ += near_.size();
    // The piece that refused the last piece tested here first: the candidates of one choice point start
    // at the same place and mostly meet the same neighbour (same answers, fewer queries before the hit).
    const auto last = std::find(near_.begin(), near_.end(), last_hit_);
    if (last != near_.end()) std::rotate(near_.begin(), last, last + 1);
    auto& against = point_.candidates[std::size_t(k)].against;
    if (s.options.record_queries && against.capacity() < against.size() + near_.size())
        against.reserve(std::max(2 * against.capacity(), against.size() + near_.size()));
    for (int id : near_) {
        const Piece& other = s.pieces[std::size_t(id)];
        QueryStats st;
        const bool hit = pieces_collide(s, mine, other, &st);
        if (!hit && mine.kind == Piece::Clip && other.kind == Piece::Clip && st.tests2d + st.tests3d <= 1 &&
            st.samples == 0)
            ++root_rejected_;
        CandidateQuery q;
        q.agent = other.agent, q.choice = other.choice, q.piece = other.index, q.hit = hit;
        record(s, k, mine, q, st);
        if (s.options.log_queries && mine.kind == Piece::Clip && other.kind == Piece::Clip)
            log_.push_back({0, k, mine.clip.clip, other.clip.clip, mine.clip.place, other.clip.place, hit});
        if (!hit || passes(id, other)) continue;
        last_hit_ = id;
        free = false;
        if (hits != Hits::Count) return false;
    }
    return free;
}

bool ChoiceQueries::piece_free(const CrowdState& s, const Piece& piece, PieceFilter skip) {
    solids_near(s, solid_box(s, piece));
    for (int i : near_) {
        count({});
        if (meets_solid(s, piece, i)) return false;
    }
    const SpaceTimeBox box = box_of(piece);
    note(box);
    query_pieces(s, box, piece.agent, near_);
    for (int id : near_) {
        const Piece& other = s.pieces[std::size_t(id)];
        if (!skip(id, other) && collide(s, piece, other)) return false;
    }
    return true;
}

bool ChoiceQueries::collide(const CrowdState& s, const Piece& mine, const Piece& other) {
    QueryStats st;
    const bool hit = pieces_collide(s, mine, other, &st);
    count(st);
    return hit;
}

bool ChoiceQueries::affected_by(const BatchGrid& chosen, int from, int below) const {
    if (queried_boxes_.empty() || from >= below) return false;
    // Their union first: most choice points are far from every other of their frame.
    if (!chosen.any_between(queried_all_, from, below)) return false;
    for (const SpaceTimeBox& b : queried_boxes_)
        if (chosen.any_between(b, from, below)) return true;
    return false;
}

int ChoiceQueries::last_change(const BatchGrid& chosen, int below) const {
    if (queried_boxes_.empty()) return -1;
    const int bound = chosen.last_between(queried_all_, 0, below);  // through their union: often none
    if (bound < 0) return -1;
    int last = -1;
    for (const SpaceTimeBox& b : queried_boxes_) {
        last = std::max(last, chosen.last_between(b, last + 1, below));
        if (last == bound) break;
    }
    return last;
}

}  // namespace mobb::crowd
