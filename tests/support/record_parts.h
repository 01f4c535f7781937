// A record read in parts (crowd/record_reader.h) put together again: its header, every frame's samples
// and every choice point, so that a test can hold it to the record read whole, field by field.
#pragma once
#include <cmath>

#include "mobb/crowd/record/record_reader.h"

namespace mobb::test {

/// The whole record from `reader`'s parts: samples() of every frame into the tracks (up to each agent's
/// left frame), choice() of every row.
inline crowd::Record record_from_parts(crowd::RecordReader& reader) {
    crowd::Record r = reader.header();
    const crowd::SampleWindow w = reader.samples(0, r.frames);
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const std::int64_t until = r.tracks[a].left_frame.value_or(r.frames);
        for (std::int64_t f = 0; f < until; ++f)
            r.tracks[a].samples.push_back(w.samples[std::size_t(f) * w.width() + a]);
    }
    for (std::size_t k = 0; k < reader.choice_count(); ++k) r.choices.push_back(reader.choice(k));
    return r;
}

/// Two windows hold the same disks, NaN where the other has NaN.
inline bool same_disks(const crowd::SampleWindow& a, const crowd::SampleWindow& b) {
    if (a.first != b.first || a.last != b.last || a.agent_first != b.agent_first || a.agent_last != b.agent_last ||
        a.samples.size() != b.samples.size())
        return false;
    for (std::size_t k = 0; k < a.samples.size(); ++k)
        for (std::size_t i = 0; i < 4; ++i)
            if (a.samples[k][i] != b.samples[k][i] && !(std::isnan(a.samples[k][i]) && std::isnan(b.samples[k][i])))
                return false;
    return true;
}

}  // namespace mobb::test
