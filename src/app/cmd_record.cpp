// mobb record convert: crowd records between JSON and HDF5 (include/mobb/crowd/record/record_file.h);
// mobb record flow: the agents' flow through a line (include/mobb/crowd/metrics/flow.h).
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "mobb/crowd/metrics/flow.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/record/record_reader.h"

namespace mobb::app {

namespace {

// Converting an HDF5 record to JSON: refused before the record is read whole when its JSON would need more
// memory than the limit (record_file.h), from the file's header and choice table alone. (A JSON record
// read is checked as it is opened.)
void check_json_target(const std::string& from, const std::string& to) {
    if (crowd::is_h5_record(to) || !crowd::is_h5_record(from)) return;
    const std::unique_ptr<crowd::RecordReader> reader = crowd::open_record(from, 0);
    const crowd::Record& h = reader->header();
    crowd::JsonRecordCounts n = crowd::expected_json_record(h.tracks.size(), h.frames, reader->choice_count(), h.select,
                                                            reader->has_candidates());
    n.clips = 0;
    for (const crowd::AgentTrack& t : h.tracks) n.clips += t.clips.size();
    crowd::check_json_record_write(to, n);
}

// Every agent's first crossing of `line`, read window by window: an HDF5 record of any size in parts.
crowd::Flow read_flow(const std::string& file, crowd::FlowLine line, std::size_t& agents) {
    constexpr std::int64_t kWindow = 600;  // frames read at once: 20 s at 30 fps
    const std::unique_ptr<crowd::RecordReader> reader = crowd::open_record(file);
    const crowd::Record& h = reader->header();
    agents = h.tracks.size();
    crowd::FlowCounter counter(line, agents);
    for (std::int64_t f = 0; f < h.frames; f += kWindow)
        counter.add(reader->samples(f, std::min(h.frames, f + kWindow)));
    return crowd::flow_of(counter.crossings());
}

void print_flow(std::ostream& out, const std::string& file, crowd::FlowLine line, std::size_t agents,
                const crowd::Flow& f, bool json) {
    const std::string axis = line.axis == 0 ? "x" : "y";
    if (json) {
        nlohmann::ordered_json j{{"file", file},         {"line", {{"axis", axis}, {"at", line.at}}},
                                 {"agents", agents},     {"crossings", f.crossings},
                                 {"forward", f.forward}, {"backward", f.backward},
                                 {"first", f.first},     {"last", f.last},
                                 {"rate", f.rate},       {"rate_from", f.rate_from},
                                 {"rate_to", f.rate_to}, {"median_headway", f.median_headway}};
        out << j.dump(1) << "\n";
        return;
    }
    out << std::fixed << std::setprecision(2) << file << ": " << f.crossings << " of " << agents << " agents crossed "
        << axis << " = " << line.at << " m (" << f.forward << " toward +" << axis << ", " << f.backward << " toward -"
        << axis << ")";
    if (f.crossings > 0) out << ", from " << f.first << " to " << f.last << " s";
    out << "; " << f.rate << " agents/s between the 10th and 90th percentile crossing (" << f.rate_from << " to "
        << f.rate_to << " s), median headway " << f.median_headway << " s\n";
}

}  // namespace

void add_record_commands(CLI::App& app, int& exit_code) {
    auto* record = app.add_subcommand("record", "Crowd records (mobb crowd --record)");
    record->require_subcommand(1);
    auto* convert = record->add_subcommand(
        "convert", "Convert a crowd record between JSON and HDF5, the kinds by extension (.h5/.hdf5: HDF5)");
    auto from = std::make_shared<std::string>(), to = std::make_shared<std::string>();
    convert->add_option("FROM", *from, "Record to read (.json or .h5)")->required();
    convert->add_option("TO", *to, "Record to write (.json or .h5)")->required();
    convert->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            check_json_target(*from, *to);
            const crowd::RecordFile r = crowd::read_record_file(*from);
            if (!r.note.empty()) std::cerr << r.note << "\n";
            crowd::write_record_file(*to, r.record, r.summary_json, r.metrics_json);
            out << *to << ": " << r.record.tracks.size() << " agents, " << r.record.frames << " frames, "
                << r.record.choices.size() << " choice points\n";
        });
    });
    auto* flow = record->add_subcommand(
        "flow",
        "Agents' flow through a line: each one's first crossing, agents/s between the 10th and 90th "
        "percentile crossing, median headway (issue 45's door target)");
    auto file = std::make_shared<std::string>(), line = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    flow->add_option("RECORD", *file, "Record to read (.json or .h5)")->required();
    flow->add_option("--line", *line, "The line: x=METRES or y=METRES (disk centres crossing it)")->required();
    flow->add_flag("--json", *json, "Print one JSON object instead of a line");
    flow->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            crowd::FlowLine l;
            try {
                l = crowd::parse_flow_line(*line);
            } catch (const std::invalid_argument& e) {
                throw InputError(std::string("--line: ") + e.what());
            }
            std::size_t agents = 0;
            const crowd::Flow f = read_flow(*file, l, agents);
            print_flow(out, *file, l, agents, f, *json);
        });
    });
}

}  // namespace mobb::app
