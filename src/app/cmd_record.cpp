// mobb record convert: crowd records between JSON and HDF5 (include/mobb/crowd/record/record_file.h).
#include <iostream>
#include <memory>

#include "cli.h"
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
}

}  // namespace mobb::app
