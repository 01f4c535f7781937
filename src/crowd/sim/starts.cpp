// Where the agents of a crowd start: at random (the paper's density, a gap apart, clear of obstacles) or
// where a scenario places them, and the ground each holds there before its first choice point.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "mobb/core/angle.h"
#include "mobb/core/assert.h"
#include "mobb/util/random.h"
#include "sim/simulation.h"

namespace mobb::crowd {

namespace {

// Random placement (each agent at a random point, tried again while it is too near one placed before) fills
// at most some 54.7 % of the ground with the agents' disks, however long it tries: the jamming limit of
// random sequential adsorption (Feder 1980; Hinrichsen, Feder and Jossang 1986). Asked for more it tried
// for minutes before failing; now it is refused at once, with about how many would fit. From a thousand
// agents on, 5 % past the limit (the attempts reach less: in 33.5 x 40 m, where it puts 948, 900 agents were
// placed and 940 were not); fewer agents are left to the attempts.
void check_room(const World& w, int agents, double gap, double margin) {
    constexpr double kJamming = 0.547;  // share of the ground under disks
    constexpr double kSpread = 1.05;
    constexpr int kFewest = 1000;
    const double ground = (w.width() - 2 * margin + gap) * (w.height() - 2 * margin + gap);
    const double fit = kJamming * ground / (kPi * gap * gap / 4);
    if (agents < kFewest || double(agents) <= kSpread * fit) return;
    std::ostringstream out;
    out << std::fixed << std::setprecision(2) << "crowd: no room for " << agents << " agents " << gap
        << " m apart in a " << w.width() << " x " << w.height() << " m world: placed at random, about "
        << std::int64_t(fit) << " fit";
    throw std::invalid_argument(out.str());
}

}  // namespace

double Simulation::max_radius() const {
    double rmax = 0;
    for (const GraphClip& c : g_.clips)
        for (const Sample& s : c.path.samples) rmax = std::max(rmax, s.r);
    return rmax;
}

// Random positions `margin` inside the world, rejected when closer than `gap` to an agent placed before
// or (with reservations) when their held ground meets an obstacle. Placed agents are kept in a grid of
// cells at least `gap` wide, so a test reads the 3 x 3 cells around the position.
void Simulation::place_at_random(double gap, double margin) {
    const World& w = o_.world;
    if (w.width() <= 2 * margin || w.height() <= 2 * margin)
        throw std::invalid_argument("crowd: world smaller than an agent");
    check_room(w, o_.agents, gap, margin);
    const double cell = std::max(gap, std::sqrt(w.width() * w.height() / double(o_.agents)));
    const int nx = int(w.width() / cell) + 1, ny = int(w.height() / cell) + 1;
    std::vector<std::vector<int>> grid(std::size_t(nx) * std::size_t(ny));
    auto cell_of = [&](double v, int n) { return std::clamp(int(v / cell), 0, n - 1); };
    auto free_at = [&](const Placement& p) {
        const int cx = cell_of(p.x - w.x0, nx), cy = cell_of(p.y - w.y0, ny);
        for (int ix = std::max(0, cx - 1); ix <= std::min(nx - 1, cx + 1); ++ix)
            for (int iy = std::max(0, cy - 1); iy <= std::min(ny - 1, cy + 1); ++iy)
                for (int b : grid[std::size_t(ix) * std::size_t(ny) + std::size_t(iy)]) {
                    const Placement& q = agents_[std::size_t(b)].start;
                    if (!(std::hypot(q.x - p.x, q.y - p.y) >= gap)) return false;
                }
        for (const Polygon& s : w.obstacles)
            if (disk_overlaps(s, p.x, p.y, margin)) return false;
        return true;
    };
    util::Random rng(o_.seed);
    agents_.reserve(std::size_t(o_.agents));
    for (int a = 0; a < o_.agents; ++a) {
        Placement p;
        bool ok = false;
        for (int attempt = 0; attempt < 100000 && !ok; ++attempt) {
            p = {rng.uniform(w.x0 + margin, w.x1 - margin), rng.uniform(w.y0 + margin, w.y1 - margin),
                 rng.uniform(-kPi, kPi), 0.0};
            ok = free_at(p);
        }
        if (!ok)
            throw std::invalid_argument("crowd: no room for " + std::to_string(o_.agents) + " agents " +
                                        std::to_string(gap) + " m apart in the world");
        grid[std::size_t(cell_of(p.x - w.x0, nx)) * std::size_t(ny) + std::size_t(cell_of(p.y - w.y0, ny))].push_back(
            a);
        agents_.emplace_back().start = p;
    }
}

// A scenario's agents, or random ones: 2 r_max apart and r_max from the edges in random mode (the
// paper's experiment), their held grounds apart and inside the walls otherwise.
void Simulation::place_agents() {
    if (o_.placed.empty()) {
        if (!policy_->avoids()) return place_at_random(2 * max_radius(), max_radius());
        return place_at_random(2 * escapes_.hold_radius, escapes_.turn_clearance);
    }
    agents_.reserve(o_.placed.size());
    for (const AgentSpec& s : o_.placed) {
        Placement p = s.start;
        p.t0 = 0;
        const auto frame = std::int64_t(std::llround(s.start_time / g_.dt()));
        Agent& a = agents_.emplace_back();
        a.start = p;
        a.start_frame = a.waiting_since = std::max<std::int64_t>(0, frame);
        a.goals = s.goals;
        a.at_goal = s.at_goal;
    }
}

// A piece in the broad phase at once, under a new id (before the first frame, no id is unused).
int Simulation::add_piece(const Piece& piece) {
    MOBB_ASSERT(unused_.empty());
    const int id = int(pieces_.size());
    pieces_.push_back(piece);
    pieces_.back().seq = placed_++;
    broad_.insert(id, piece.agent, box_of(piece));
    return id;
}

// Every agent's held ground where it starts: the escape of its first choice point. Scenario agents must
// start apart, their held ground as clear of the solids as any other (CrowdState::hold_clearance: room to
// stand for goal agents, to turn for wanderers; checked here).
void Simulation::reserve_starts() {
    for (int a = 0; a < int(agents_.size()); ++a) {
        Agent& agent = agents_[std::size_t(a)];
        const Hold h{agent.start.x, agent.start.y, escapes_.hold_radius, 0};
        for (const Polygon& s : solids_)
            if (disk_overlaps(s, h.x, h.y, hold_clearance_))
                throw std::invalid_argument("crowd: agent " + std::to_string(a) + " starts within " +
                                            std::to_string(hold_clearance_) + " m of a wall or an obstacle");
        for (int b = 0; b < a && !o_.placed.empty(); ++b) {  // random starts are placed apart
            const Placement& q = agents_[std::size_t(b)].start;
            if (std::hypot(q.x - h.x, q.y - h.y) < 2 * h.r)
                throw std::invalid_argument("crowd: agents " + std::to_string(b) + " and " + std::to_string(a) +
                                            " start closer than " + std::to_string(2 * h.r) + " m");
        }
        Piece p;
        p.kind = Piece::Held;
        p.agent = a;
        p.choice = -1;
        p.index = -1;
        p.hold = h;
        agent.plan.hold = h;
        agent.reserved.push_back(add_piece(p));
    }
}

}  // namespace mobb::crowd
