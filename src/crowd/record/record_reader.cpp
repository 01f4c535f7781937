// Records read in parts (include/mobb/crowd/record/record_reader.h): a JSON record held whole and answered from
// memory; windows of a whole record. The HDF5 reader is record_h5_window.cpp.
#include "mobb/crowd/record/record_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mobb::crowd {

std::unique_ptr<RecordReader> open_h5_reader(const std::string& file, std::size_t cache_bytes);  // record_h5_window.cpp

namespace {

// A record read whole (JSON): its parts are views of it.
class WholeReader final : public RecordReader {
public:
    WholeReader(std::string file, RecordFile read) : file_(std::move(file)), whole_(std::move(read.record)) {
        info_ = std::move(read);
        Record& h = info_.record;
        h.graph = whole_.graph, h.tree = whole_.tree, h.select = whole_.select, h.scenario = whole_.scenario;
        h.dt = whole_.dt, h.frames = whole_.frames, h.world = whole_.world, h.seed = whole_.seed;
        h.tracks.clear();
        for (const AgentTrack& t : whole_.tracks) {
            h.tracks.push_back(t);
            h.tracks.back().samples.clear();
            h.tracks.back().samples.shrink_to_fit();
        }
        h.choices.clear();
        counts_.frames = whole_.frames;
    }

    const Record& header() override { return info_.record; }
    const RecordFile& info() const override { return info_; }
    std::size_t choice_count() const override { return whole_.choices.size(); }
    bool lazy() const override { return false; }
    bool has_candidates() const override {
        return std::any_of(whole_.choices.begin(), whole_.choices.end(),
                           [](const ChoicePoint& c) { return !c.candidates.empty(); });
    }

    SampleWindow samples(std::int64_t first, std::int64_t last, AgentRange agents) override {
        SampleWindow w = window_of(whole_, first, last, agents);
        w.summary_json = info_.summary_json;
        w.metrics_json = info_.metrics_json;
        w.note = info_.note;
        counts_.cached += w.last - w.first;
        return w;
    }

    std::pair<std::size_t, std::size_t> choice_rows(std::int64_t first_frame, std::int64_t last_frame) override {
        const auto& c = whole_.choices;
        const auto at = [&](std::int64_t frame) {
            return std::size_t(std::lower_bound(c.begin(), c.end(), frame,
                                                [](const ChoicePoint& p, std::int64_t f) { return p.frame < f; }) -
                               c.begin());
        };
        const std::size_t lo = at(first_frame);
        return {lo, std::max(lo, at(last_frame))};
    }

    std::vector<ChoiceSummary> summaries(std::size_t first, std::size_t last, int agent) override {
        last = std::min(last, whole_.choices.size());
        std::vector<ChoiceSummary> out;
        for (std::size_t k = std::min(first, last); k < last; ++k) {
            const ChoicePoint& c = whole_.choices[k];
            if (agent >= 0 && c.agent != agent) continue;
            ChoiceSummary s{k, c, c.candidates.size()};
            s.point.candidates.clear();
            s.point.escape.clear();
            s.point.intended.clear();
            s.point.reroutes.clear();
            out.push_back(std::move(s));
        }
        counts_.table_rows += std::int64_t(last - std::min(first, last));
        return out;
    }

    ChoicePoint choice(std::size_t row) override {
        if (row >= whole_.choices.size())
            throw std::out_of_range(file_ + ": choice point " + std::to_string(row) + ", the record has " +
                                    std::to_string(whole_.choices.size()));
        ++counts_.choices;
        return whole_.choices[row];
    }

    std::vector<ChoiceMark> fallbacks() override {
        std::vector<ChoiceMark> out;
        for (std::size_t k = 0; k < whole_.choices.size(); ++k)
            if (whole_.choices[k].fallback) out.push_back({k, whole_.choices[k].agent, whole_.choices[k].frame});
        counts_.table_rows += std::int64_t(whole_.choices.size());
        return out;
    }

    ReadCounts counts() const override { return counts_; }
    void check_graph_clips(std::size_t clips) override { crowd::check_graph_clips(whole_, clips); }

private:
    std::string file_;
    Record whole_;
    RecordFile info_;  // record: the header
    ReadCounts counts_;
};

}  // namespace

std::unique_ptr<RecordReader> open_record(const std::string& file, std::size_t cache_bytes) {
    if (is_h5_record(file)) return open_h5_reader(file, cache_bytes);
    return std::make_unique<WholeReader>(file, read_record_file(file));
}

SampleWindow window_of(const Record& r, std::int64_t first, std::int64_t last, AgentRange agents) {
    SampleWindow w;
    w.dt = r.dt;
    w.frames = r.frames;
    w.agents = r.tracks.size();
    w.first = std::clamp<std::int64_t>(first, 0, w.frames);
    w.last = std::clamp<std::int64_t>(last, w.first, w.frames);
    w.agent_first = std::min(agents.first, w.agents);
    w.agent_last = std::clamp(agents.last, w.agent_first, w.agents);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    w.samples.reserve(std::size_t(w.last - w.first) * w.width());
    for (std::int64_t f = w.first; f < w.last; ++f)
        for (std::size_t a = w.agent_first; a < w.agent_last; ++a) {
            const auto& s = r.tracks[a].samples;
            w.samples.push_back(f < std::int64_t(s.size()) ? s[std::size_t(f)]
                                                           : std::array<double, 4>{nan, nan, nan, nan});
        }
    return w;
}

const std::array<double, 4>* window_disk(const SampleWindow& w, std::size_t agent, std::int64_t frame) {
    if (frame < w.first || frame >= w.last || agent < w.agent_first || agent >= w.agent_last) return nullptr;
    const std::array<double, 4>& d = w.samples[std::size_t(frame - w.first) * w.width() + (agent - w.agent_first)];
    return std::isnan(d[0]) ? nullptr : &d;
}

SampleWindow read_sample_window(const std::string& file, std::int64_t first, std::int64_t last) {
    return open_record(file, 0)->samples(first, last);
}

}  // namespace mobb::crowd
