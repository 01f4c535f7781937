// An HDF5 crowd record read in parts (record_reader.h; the layout in docs/formats.md): the header, goals,
// left frames and clips when it opens; samples a block of frames at a time, kept in a bounded cache; a
// range of the choice table's rows, or one choice point with its candidates, queries and plan, found by
// binary search on the owner columns of the nested tables (each table is in its owner's order). What is
// read is checked as the whole reader checks it: a choice point through the JSON reader, the rest value
// by value in its words, places named as in the JSON layout.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <list>
#include <map>
#include <optional>
#include <stdexcept>

#include "mobb/crowd/record/record_reader.h"
#include "mobb/util/json_text.h"
#include "record/frame_blocks.h"
#include "record/h5.h"
#include "record/record_h5_read.h"
#include "record/record_json.h"

namespace mobb::crowd {

namespace {

using J = nlohmann::ordered_json;
using I = std::vector<std::int64_t>;
using D = std::vector<double>;
using h5::Column;

// Rows of a table read and checked at a time while the clip table is read (a block of the file's).
constexpr hsize_t kTableBlock = 4096;

[[noreturn]] void bad(const std::string& place, const std::string& message) { throw h5::Error(place + ": " + message); }

// Row `row` of a nested table names its owner's row `value`, one of lo .. hi - 1 (the rows its binary
// search found): its index from lo. A column out of its owners' order (a damaged file) is refused.
std::size_t owner(std::int64_t value, hsize_t lo, hsize_t hi, const std::string& path, hsize_t row) {
    if (value < std::int64_t(lo) || value >= std::int64_t(hi))
        bad(path + " row " + std::to_string(row), std::to_string(value) + ": not in its owners' order");
    return std::size_t(value - std::int64_t(lo));
}

class H5Reader final : public RecordReader {
public:
    H5Reader(const std::string& file, std::size_t cache_bytes);

    const Record& header() override {
        if (!clips_read_) named([&] { read_clips(); });
        return info_.record;
    }
    const RecordFile& info() const override { return info_; }
    std::size_t choice_count() const override { return choices_; }
    bool lazy() const override { return true; }
    bool has_candidates() const override { return has_candidates_; }
    SampleWindow samples(std::int64_t first, std::int64_t last, AgentRange agents) override;
    std::pair<std::size_t, std::size_t> choice_rows(std::int64_t first_frame, std::int64_t last_frame) override;
    std::vector<ChoiceSummary> summaries(std::size_t first, std::size_t last, int agent) override;
    ChoicePoint choice(std::size_t row) override;
    std::vector<ChoiceMark> fallbacks() override;
    ReadCounts counts() const override { return counts_; }
    void check_graph_clips(std::size_t clips) override {
        crowd::check_graph_clips(header(), clips);
        graph_clips_ = clips;
    }

private:
    using Block = std::shared_ptr<const std::vector<std::array<double, 4>>>;

    // Every call that reads puts the file's name in front of an h5::Error.
    template <class F>
    auto named(F&& f) -> decltype(f()) {
        try {
            return f();
        } catch (const h5::Error& e) {
            throw std::runtime_error(file_ + ": " + e.what());
        } catch (const FieldError& e) {
            throw std::runtime_error(file_ + ": " + e.what());
        }
    }
    void open_header();
    void read_tracks();
    void read_goals();
    void read_clips();
    void count_choices();
    I left_by_samples();
    Column<std::int64_t>& ints(const std::string& path);
    Column<double>& reals(const std::string& path, hsize_t width);
    void same_rows(const std::string& path, hsize_t rows);
    Block block(std::int64_t k, bool& cached);
    void check_block(std::int64_t k, const std::vector<std::array<double, 4>>& disks) const;
    std::pair<hsize_t, hsize_t> owned(const std::string& owner_path, hsize_t first, hsize_t last);
    J framed(const std::string& group, const char* owner_name, std::size_t row);
    J reroutes(std::size_t row);
    J candidates(std::size_t row);

    std::string file_;
    h5::Id f_;
    h5read::Held held_;
    RecordFile info_;  // record: the header
    bool older_ = false, random_ = false;
    std::size_t agents_ = 0;
    std::int64_t frames_ = 0, block_frames_ = 1;
    std::vector<std::int64_t> until_;  // per agent: the frame its samples end (it left, or the run's end)
    Column<double> samples_;
    std::map<std::string, Column<std::int64_t>> ints_;
    std::map<std::string, Column<double>> reals_;
    std::size_t choices_ = 0;
    hsize_t choice_rows_ = 0;  // rows of the /choices columns (those of an incomplete file's later frames too)
    // The cache: blocks of frames by their index, most recently used first.
    std::list<std::pair<std::int64_t, Block>> recent_;
    std::size_t cache_bytes_ = 0, cached_bytes_ = 0;
    ReadCounts counts_;
    bool clips_read_ = false;                 // header(): the clip table is read on its first call
    bool has_candidates_ = false;             // /candidates holds rows (those held of an incomplete file)
    std::optional<std::size_t> graph_clips_;  // check_graph_clips: the choice points read are checked too
};

H5Reader::H5Reader(const std::string& file, std::size_t cache_bytes) : file_(file), cache_bytes_(cache_bytes) {
    h5::quiet();
    if (H5Fis_hdf5(file.c_str()) <= 0)
        throw std::runtime_error(file + ": not an HDF5 file (or truncated before its superblock)");
    named([&] {
        f_ = h5::Id(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
        if (!f_.valid()) throw h5::Error("cannot open (truncated or corrupt)");
        open_header();
        count_choices();
        has_candidates_ = ints("/candidates/choice").rows() > 0;
        read_tracks();
        read_goals();
    });
}

void H5Reader::open_header() {
    J j = h5read::header(f_.get(), held_);
    j["obstacles"] = h5read::obstacles(f_.get());
    const std::int64_t agents = j["agents"].get<std::int64_t>();
    if (agents < 1 || agents > 10'000'000) throw h5::Error("attribute agents: expected 1 to 10,000,000");
    info_.record = record_header_from_json(j, file_);
    agents_ = std::size_t(agents);
    frames_ = info_.record.frames;
    older_ = j["version"].get<std::int64_t>() < kRecordVersion;
    random_ = info_.record.select == "random";
    info_.record.tracks.resize(agents_);
    info_.summary_json = stored_summary(j);
    if (j.contains("metrics")) info_.metrics_json = j["metrics"].dump();
    info_.note = h5read::note(file_, held_);
    block_frames_ = block_frames(agents_);
    samples_ = Column<double>(f_.get(), "/tracks/samples", {hsize_t(agents_), 4}, hsize_t(block_frames_),
                              held_.complete ? ~hsize_t(0) : hsize_t(frames_));
    if (std::int64_t(samples_.rows()) != frames_)
        throw h5::Error("/tracks/samples: " + std::to_string(samples_.rows()) + " frames, the record has " +
                        std::to_string(frames_));
}

Column<std::int64_t>& H5Reader::ints(const std::string& path) {
    auto it = ints_.find(path);
    if (it == ints_.end()) {
        it = ints_.emplace(path, Column<std::int64_t>(f_.get(), path, {}, 4096, held_.limit(path))).first;
        same_rows(path, it->second.rows());
    }
    return it->second;
}

Column<double>& H5Reader::reals(const std::string& path, hsize_t width) {
    auto it = reals_.find(path);
    if (it == reals_.end()) {
        it = reals_.emplace(path, Column<double>(f_.get(), path, {width}, 4096, held_.limit(path))).first;
        same_rows(path, it->second.rows());
    }
    return it->second;
}

// Every column of a table has as many rows as its first (the table's first column as the writer names it).
void H5Reader::same_rows(const std::string& path, hsize_t rows) {
    static const std::map<std::string, std::string> kFirst = {
        {"/choices", "agent"},     {"/clips", "agent"},       {"/escapes", "choice"},
        {"/intended", "choice"},   {"/reroutes", "choice"},   {"/reroute_escapes", "reroute"},
        {"/candidates", "choice"}, {"/queries", "candidate"}, {"/goals", "agent"},
        {"/tracks", "at_goal"}};
    const std::string group = path.substr(0, path.rfind('/'));
    const auto it = kFirst.find(group);
    if (it == kFirst.end() || path == group + "/" + it->second) return;
    const hsize_t n = ints(group + "/" + it->second).rows();
    if (rows != n)
        throw h5::Error(path + ": " + std::to_string(rows) + " rows, " + group + " has " + std::to_string(n));
}

// The choice points of the frames held: all rows of a finished file; of an incomplete one, those before its
// last mark's frame (the table is in frame order).
void H5Reader::count_choices() {
    Column<std::int64_t>& frame = ints("/choices/frame");
    choice_rows_ = ints("/choices/agent").rows();
    choices_ = std::size_t(held_.complete ? choice_rows_ : frame.lower_bound(frames_, 0, choice_rows_));
}

// An incomplete file's agents that left: the first frame of NaN in its samples (finish() writes the frames
// they left at), found block by block.
I H5Reader::left_by_samples() {
    I left(agents_, -1);
    for (std::int64_t k = 0; k * block_frames_ < frames_; ++k) {
        const std::int64_t f0 = k * block_frames_, n = std::min(block_frames_, frames_ - f0);
        const D v = samples_.read(hsize_t(f0), hsize_t(n));
        counts_.frames += n;
        for (std::int64_t f = 0; f < n; ++f)
            for (std::size_t a = 0; a < agents_; ++a)
                if (left[a] < 0 && std::isnan(v[(std::size_t(f) * agents_ + a) * 4])) left[a] = f0 + f;
    }
    return left;
}

void H5Reader::read_tracks() {
    const I left =
        held_.complete ? ints("/tracks/left_frame").read(0, ints("/tracks/left_frame").rows()) : left_by_samples();
    Column<std::int64_t>& at_goal = ints("/tracks/at_goal");
    if (left.size() != agents_ || at_goal.rows() != agents_)
        throw h5::Error("/tracks/left_frame: " + std::to_string(left.size()) + " rows, /tracks/at_goal " +
                        std::to_string(at_goal.rows()) + ", the record has " + std::to_string(agents_) + " agents");
    const I leaves = at_goal.read(0, agents_);
    until_.assign(agents_, frames_);
    for (std::size_t a = 0; a < agents_; ++a) {
        AgentTrack& t = info_.record.tracks[a];
        t.at_goal = leaves[a] ? AtGoal::Leave : AtGoal::Stay;
        if (left[a] < 0) continue;
        if (left[a] < 1 || left[a] > frames_ - 1)
            bad(element_place("tracks", a) + ".left_frame",
                std::to_string(left[a]) + ": expected 1 to " + std::to_string(frames_ - 1));
        if (t.at_goal != AtGoal::Leave)
            bad(element_place("tracks", a) + ".left_frame", "only an agent that leaves has one");
        t.left_frame = left[a];
        until_[a] = left[a];
    }
}

void H5Reader::read_goals() {
    Column<std::int64_t>& agent = ints("/goals/agent");
    Column<double>& xy = reals("/goals/xy", 2);
    const I of = agent.read(0, agent.rows());
    const D v = xy.read(0, xy.rows());
    for (std::size_t k = 0; k < of.size(); ++k) {
        if (of[k] < 0 || std::size_t(of[k]) >= agents_)
            bad("/goals/agent row " + std::to_string(k),
                std::to_string(of[k]) + ", there are " + std::to_string(agents_));
        AgentTrack& t = info_.record.tracks[std::size_t(of[k])];
        const auto place = [&, a = of[k], g = t.goals.size()](std::size_t i) {
            return
                [=] { return element_place(element_place(element_place("tracks", std::size_t(a)) + ".goals", g), i); };
        };
        check_coordinate(v[2 * k], place(0));
        check_coordinate(v[2 * k + 1], place(1));
        t.goals.push_back({v[2 * k], v[2 * k + 1]});
    }
    for (std::size_t a = 0; a < agents_; ++a)
        if (info_.record.tracks[a].goals.empty() && info_.record.tracks[a].at_goal == AtGoal::Leave)
            bad(element_place("tracks", a) + ".at_goal", "an agent without a goal has none");
}

// The clip table, a block of rows at a time: each clip checked as the JSON reader checks a track's clips.
void H5Reader::read_clips() {
    for (AgentTrack& t : info_.record.tracks) t.clips.clear();  // a read that failed before left some
    const std::string taker = older_ ? "/clips/commit" : "/clips/choice";
    Column<std::int64_t>&agent = ints("/clips/agent"), &clip = ints("/clips/clip"), &start = ints("/clips/start"),
    &fallback = ints("/clips/fallback"), &choice = ints(taker);
    Column<double>& places = reals("/clips/place", 4);
    const double dt = info_.record.dt;
    // Each agent's clips counted first, so that its list is allocated once (5 M clips at 100,000 agents);
    // an owner out of range is named below, in row order, unless past an incomplete file's last mark.
    const I owner = agent.read(0, agent.rows());
    std::vector<std::size_t> count(agents_, 0);
    for (const std::int64_t a : owner)
        if (a >= 0 && std::size_t(a) < agents_) ++count[std::size_t(a)];
    for (std::size_t a = 0; a < agents_; ++a) info_.record.tracks[a].clips.reserve(count[a]);
    for (hsize_t r0 = 0; r0 < agent.rows(); r0 += kTableBlock) {
        const hsize_t n = std::min(kTableBlock, agent.rows() - r0);
        const I c = clip.read(r0, n), s = start.read(r0, n), fb = fallback.read(r0, n), ch = choice.read(r0, n);
        const D p = places.read(r0, n);
        const std::int64_t* a = owner.data() + r0;
        for (std::size_t k = 0; k < n; ++k) {
            if (!held_.complete && s[k] >= frames_) continue;  // an incomplete file: the clips of its frames
            if (a[k] < 0 || std::size_t(a[k]) >= agents_)
                bad("/clips/agent row " + std::to_string(r0 + k),
                    std::to_string(a[k]) + ", there are " + std::to_string(agents_));
            std::vector<PlacedClip>& clips = info_.record.tracks[std::size_t(a[k])].clips;
            const auto w = [&, agent = std::size_t(a[k]), n = clips.size()](const char* key) {
                return element_place(element_place("tracks", agent) + ".clips", n) + key;
            };
            const PlacedClip* before = clips.empty() ? nullptr : &clips.back();
            if (c[k] < 0 || c[k] > std::numeric_limits<int>::max())
                bad(w(".clip"), std::to_string(c[k]) + ": expected at least 0");
            if (s[k] < 0 || s[k] >= frames_)
                bad(w(".start"), std::to_string(s[k]) + ": expected 0 to " + std::to_string(frames_ - 1));
            if (!before && s[k] != 0)
                bad(w(".start"), std::to_string(s[k]) + ": an agent's first clip starts at frame 0");
            if (before && s[k] <= before->start)
                bad(w(".start"), std::to_string(s[k]) + ": clips in time order, the one before starts at frame " +
                                     std::to_string(before->start));
            const double* q = &p[4 * k];
            if (!disk_ok({q[3], q[0], q[1], 0.0}, s[k], dt) || !std::isfinite(q[2])) {  // the checks for the message
                const auto place = [&](std::size_t i) { return [&w, i] { return element_place(w(".place"), i); }; };
                check_coordinate(q[0], place(0));
                check_coordinate(q[1], place(1));
                check_finite(q[2], place(2));
                check_frame_time(q[3], s[k], dt, 1e-9, place(3));
            }
            if (ch[k] < -1 || ch[k] >= std::int64_t(choices_))
                bad(w(".choice"),
                    std::to_string(ch[k]) + ": the record has " + std::to_string(choices_) + " choice points");
            if (before && ch[k] < before->choice)
                bad(w(".choice"), std::to_string(ch[k]) + ": choice points in order, the clip before's is " +
                                      std::to_string(before->choice));
            clips.push_back({int(c[k]), s[k], {q[0], q[1], q[2], q[3]}, fb[k] != 0, ch[k]});
        }
    }
    for (std::size_t a = 0; a < agents_; ++a)
        if (info_.record.tracks[a].clips.empty())
            bad(element_place("tracks", a) + ".clips", "an agent plays at least one clip");
    clips_read_ = true;
}

// Each disk of an agent still in the run checked as the JSON reader checks a track's samples.
void H5Reader::check_block(std::int64_t k, const std::vector<std::array<double, 4>>& disks) const {
    const std::int64_t f0 = k * block_frames_;
    const double dt = info_.record.dt;
    for (std::size_t i = 0; i < disks.size(); ++i) {
        const std::int64_t f = f0 + std::int64_t(i / agents_);
        const std::size_t a = i % agents_;
        if (f >= until_[a]) continue;
        const std::array<double, 4>& d = disks[i];
        if (disk_ok(d, f, dt)) continue;  // the checks below only for their message
        const auto place = [&](std::size_t j) {
            return [=] {
                return element_place(element_place(element_place("tracks", a) + ".samples", std::size_t(f)), j);
            };
        };
        check_finite(d[0], place(0));
        check_frame_time(d[0], f, dt, 1e-9, place(0));
        check_coordinate(d[1], place(1));
        check_coordinate(d[2], place(2));
        check_radius(d[3], place(3));
        bad(place(0)(), "a disk out of range");  // disk_ok and the checks disagree: not expected
    }
}

// Block k of the samples (frames k * block_frames_ on), from the cache or read, checked and cached.
H5Reader::Block H5Reader::block(std::int64_t k, bool& cached) {
    cached = true;
    for (auto it = recent_.begin(); it != recent_.end(); ++it)
        if (it->first == k) {
            recent_.splice(recent_.begin(), recent_, it);
            return it->second;
        }
    cached = false;
    const std::int64_t f0 = k * block_frames_, n = std::min(block_frames_, frames_ - f0);
    const D v = samples_.read(hsize_t(f0), hsize_t(n));
    auto disks = std::make_shared<std::vector<std::array<double, 4>>>(v.size() / 4);
    for (std::size_t i = 0; i < disks->size(); ++i) std::copy_n(&v[4 * i], 4, (*disks)[i].begin());
    check_block(k, *disks);
    counts_.frames += n;
    const std::size_t bytes = disks->size() * sizeof(std::array<double, 4>);
    if (bytes <= cache_bytes_) {
        while (cached_bytes_ + bytes > cache_bytes_ && !recent_.empty()) {
            cached_bytes_ -= recent_.back().second->size() * sizeof(std::array<double, 4>);
            recent_.pop_back();
        }
        recent_.emplace_front(k, disks);
        cached_bytes_ += bytes;
    }
    return disks;
}

SampleWindow H5Reader::samples(std::int64_t first, std::int64_t last, AgentRange agents) {
    SampleWindow w;
    w.dt = info_.record.dt;
    w.frames = frames_;
    w.agents = agents_;
    w.first = std::clamp<std::int64_t>(first, 0, frames_);
    w.last = std::clamp<std::int64_t>(last, w.first, frames_);
    w.agent_first = std::min(agents.first, agents_);
    w.agent_last = std::clamp(agents.last, w.agent_first, agents_);
    w.summary_json = info_.summary_json;
    w.metrics_json = info_.metrics_json;
    w.note = info_.note;
    w.samples.resize(std::size_t(w.last - w.first) * w.width());
    named([&] {
        for (std::int64_t f = w.first; f < w.last;) {
            const std::int64_t k = f / block_frames_, f0 = k * block_frames_;
            bool cached = false;
            const Block b = block(k, cached);
            const std::int64_t until = std::min(w.last, f0 + std::int64_t(b->size() / agents_));
            if (cached) counts_.cached += until - f;
            for (; f < until; ++f)
                std::copy_n(b->begin() + std::ptrdiff_t(std::size_t(f - f0) * agents_ + w.agent_first), w.width(),
                            w.samples.begin() + std::ptrdiff_t(std::size_t(f - w.first) * w.width()));
        }
    });
    return w;
}

std::pair<std::size_t, std::size_t> H5Reader::choice_rows(std::int64_t first_frame, std::int64_t last_frame) {
    return named([&] {
        Column<std::int64_t>& frame = ints("/choices/frame");
        const hsize_t lo = frame.lower_bound(first_frame, 0, choices_);
        return std::pair<std::size_t, std::size_t>(lo, std::max(lo, frame.lower_bound(last_frame, lo, choices_)));
    });
}

// The rows [first, last) of a nested table whose owner (column `owner_path`, in owner order) is one of
// rows first .. last - 1 of its owner table.
std::pair<hsize_t, hsize_t> H5Reader::owned(const std::string& owner_path, hsize_t first, hsize_t last) {
    Column<std::int64_t>& column = ints(owner_path);
    const hsize_t lo = column.lower_bound(std::int64_t(first), 0, column.rows());
    return {lo, std::max(lo, column.lower_bound(std::int64_t(last), lo, column.rows()))};
}

std::vector<ChoiceSummary> H5Reader::summaries(std::size_t first, std::size_t last, int agent) {
    static const char* const kNames[] = {"agent",   "frame",   "taken",   "outcome", "fallback",  "queries",
                                         "tests2d", "tests3d", "samples", "pruned",  "hold_frame"};
    last = std::min(last, choices_);
    first = std::min(first, last);
    const hsize_t n = last - first;
    return named([&] {
        std::vector<I> c;
        for (const char* name : kNames) c.push_back(ints(std::string("/choices/") + name).read(first, n));
        const D hold = reals("/choices/hold", 3).read(first, n);
        const auto [k0, k1] = owned("/candidates/choice", first, last);
        const I owners = ints("/candidates/choice").read(k0, k1 - k0);
        std::vector<std::size_t> tested(n, 0);
        for (std::size_t k = 0; k < owners.size(); ++k)
            ++tested[owner(owners[k], first, last, "/candidates/choice", k0 + k)];
        std::vector<ChoiceSummary> out;
        for (std::size_t k = 0; k < n; ++k) {
            if (agent >= 0 && c[0][k] != agent) continue;
            const auto w = [&, row = first + k] { return element_place("choices", row); };
            ChoicePoint& p = out.emplace_back().point;
            out.back().row = first + k;
            out.back().candidates = tested[k];
            if (c[0][k] < 0 || std::size_t(c[0][k]) >= agents_)
                bad(w() + ".agent", std::to_string(c[0][k]) + ": expected 0 to " + std::to_string(agents_ - 1));
            if (c[1][k] < 0 || c[1][k] >= frames_)
                bad(w() + ".frame", std::to_string(c[1][k]) + ": expected 0 to " + std::to_string(frames_ - 1));
            if (c[2][k] < 0 || c[2][k] > std::numeric_limits<int>::max()) bad(w() + ".taken", "expected a clip id");
            if (c[3][k] < 0 || c[3][k] > 4) bad("/choices/outcome row " + std::to_string(first + k), "expected 0 to 4");
            for (std::size_t i = 5; i < 10; ++i)
                if (c[i][k] < 0) bad(w() + "." + kNames[i], "expected a count (an integer, not negative)");
            p.agent = int(c[0][k]);
            p.frame = c[1][k];
            p.taken = int(c[2][k]);
            p.outcome = h5read::kOutcomes[c[3][k]];
            p.fallback = c[4][k] != 0;
            p.queries = std::uint64_t(c[5][k]), p.tests2d = std::uint64_t(c[6][k]), p.tests3d = std::uint64_t(c[7][k]);
            p.samples = std::uint64_t(c[8][k]), p.pruned = std::uint64_t(c[9][k]);
            if (c[10][k] >= 0) {
                const auto place = [&](std::size_t i) { return [=] { return element_place(w() + ".plan.hold", i); }; };
                check_coordinate(hold[3 * k], place(0));
                check_coordinate(hold[3 * k + 1], place(1));
                check_radius(hold[3 * k + 2], place(2));
                p.holds = true;
                p.hold = {hold[3 * k], hold[3 * k + 1], hold[3 * k + 2]};
                p.hold_frame = c[10][k];
            }
        }
        counts_.table_rows += std::int64_t(n);
        return out;
    });
}

// A plan's clips of choice point `row` from table `group` ([clip, frame, x, y, theta] rows).
J H5Reader::framed(const std::string& group, const char* owner_name, std::size_t row) {
    const auto [e0, e1] = owned(group + "/" + owner_name, row, row + 1);
    const I clip = ints(group + "/clip").read(e0, e1 - e0), frame = ints(group + "/frame").read(e0, e1 - e0);
    const D place = reals(group + "/place", 3).read(e0, e1 - e0);
    J out = J::array();
    for (std::size_t k = 0; k < clip.size(); ++k)
        out.push_back({clip[k], frame[k], place[3 * k], place[3 * k + 1], place[3 * k + 2]});
    return out;
}

J H5Reader::reroutes(std::size_t row) {
    const auto [r0, r1] = owned("/reroutes/choice", row, row + 1);
    const I agent = ints("/reroutes/agent").read(r0, r1 - r0), frame = ints("/reroutes/hold_frame").read(r0, r1 - r0);
    const D hold = reals("/reroutes/hold", 3).read(r0, r1 - r0);
    J out = J::array();
    for (std::size_t k = 0; k < agent.size(); ++k)
        out.push_back({{"agent", agent[k]},
                       {"escape", J::array()},
                       {"hold", {hold[3 * k], hold[3 * k + 1], hold[3 * k + 2], frame[k]}}});
    const auto [e0, e1] = owned("/reroute_escapes/reroute", r0, r1);
    const I owners = ints("/reroute_escapes/reroute").read(e0, e1 - e0);
    const I clip = ints("/reroute_escapes/clip").read(e0, e1 - e0);
    const I eframe = ints("/reroute_escapes/frame").read(e0, e1 - e0);
    const D place = reals("/reroute_escapes/place", 3).read(e0, e1 - e0);
    for (std::size_t k = 0; k < owners.size(); ++k)
        out[owner(owners[k], r0, r1, "/reroute_escapes/reroute", e0 + k)]["escape"].push_back(
            {clip[k], eframe[k], place[3 * k], place[3 * k + 1], place[3 * k + 2]});
    return out;
}

// The candidates of choice point `row` with their queries, in today's names (a version 2 file's one flag
// "outside" is leaves_world in a random-mode record, meets_solid otherwise; its queries' index "commit").
J H5Reader::candidates(std::size_t row) {
    static const std::vector<const char*> kNames = {"clip",    "leaves_world", "meets_solid",
                                                    "queries", "hits",         "crowded"};
    static const std::vector<const char*> kOlder = {"clip", "outside", "queries", "hits", "crowded"};
    const auto [k0, k1] = owned("/candidates/choice", row, row + 1);
    std::map<std::string, I> c;
    for (const char* name : older_ ? kOlder : kNames)
        c[name] = ints(std::string("/candidates/") + name).read(k0, k1 - k0);
    const auto [q0, q1] = owned("/queries/candidate", k0, k1);
    std::vector<I> q;
    for (const char* name : {"candidate", "agent", older_ ? "commit" : "index", "piece", "mine", "hit"})
        q.push_back(ints(std::string("/queries/") + name).read(q0, q1 - q0));
    J out = J::array();
    for (std::size_t k = 0; k < k1 - k0; ++k) {
        J cand = {{"clip", c["clip"][k]}};
        const bool outside = older_ && c["outside"][k] != 0;
        cand["leaves_world"] = older_ ? random_ && outside : c["leaves_world"][k] != 0;
        cand["meets_solid"] = older_ ? !random_ && outside : c["meets_solid"][k] != 0;
        cand["queries"] = c["queries"][k];
        cand["hits"] = c["hits"][k];
        cand["against"] = J::array();
        if (c["crowded"][k]) cand["crowded"] = true;
        out.push_back(std::move(cand));
    }
    for (std::size_t k = 0; k < q[0].size(); ++k)
        out[owner(q[0][k], k0, k1, "/queries/candidate", q0 + k)]["against"].push_back(
            {q[1][k], q[2][k], q[3][k], q[4][k], q[5][k]});
    return out;
}

ChoicePoint H5Reader::choice(std::size_t row) {
    if (row >= choices_)
        throw std::out_of_range(file_ + ": choice point " + std::to_string(row) + ", the record has " +
                                std::to_string(choices_));
    J c = named([&] {
        ChoiceSummary s = summaries(row, row + 1, -1).front();
        const ChoicePoint& p = s.point;
        J plan = {{"escape", framed("/escapes", "choice", row)}};
        if (J intended = framed("/intended", "choice", row); !intended.empty()) plan["intended"] = std::move(intended);
        if (p.holds) plan["hold"] = {p.hold[0], p.hold[1], p.hold[2], p.hold_frame};
        if (J r = reroutes(row); !r.empty()) plan["reroutes"] = std::move(r);
        return J{{"agent", p.agent},
                 {"frame", p.frame},
                 {"t", util::rounded(double(p.frame) * info_.record.dt, 9)},
                 {"taken", p.taken},
                 {"outcome", p.outcome},
                 {"fallback", p.fallback},
                 {"queries", p.queries},
                 {"tests2d", p.tests2d},
                 {"tests3d", p.tests3d},
                 {"samples", p.samples},
                 {"pruned", p.pruned},
                 {"plan", std::move(plan)},
                 {"candidates", candidates(row)}};
    });
    ++counts_.choices;
    ChoicePoint out = choice_from_json(c, info_.record, row, file_);
    try {
        if (graph_clips_) check_choice_clips(out, row, *graph_clips_, info_.record.graph);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(file_ + ": " + e.what());
    }
    return out;
}

std::vector<ChoiceMark> H5Reader::fallbacks() {
    return named([&] {
        std::vector<ChoiceMark> out;
        Column<std::int64_t>&fallback = ints("/choices/fallback"), &agent = ints("/choices/agent"),
        &frame = ints("/choices/frame");
        for (hsize_t r0 = 0; r0 < choices_; r0 += kTableBlock) {
            const I v = fallback.read(r0, std::min<hsize_t>(kTableBlock, choices_ - r0));
            for (std::size_t k = 0; k < v.size(); ++k)
                if (v[k]) {
                    const std::int64_t a = agent.at(r0 + k), f = frame.at(r0 + k);
                    if (a < 0 || std::size_t(a) >= agents_ || f < 0 || f >= frames_)
                        bad(element_place("choices", r0 + k), "agent " + std::to_string(a) + " at frame " +
                                                                  std::to_string(f) +
                                                                  ": not an agent and a frame of the record");
                    out.push_back({std::size_t(r0 + k), int(a), f});
                }
        }
        counts_.table_rows += std::int64_t(choices_);
        return out;
    });
}

}  // namespace

std::unique_ptr<RecordReader> open_h5_reader(const std::string& file, std::size_t cache_bytes) {
    return std::make_unique<H5Reader>(file, cache_bytes);
}

}  // namespace mobb::crowd
