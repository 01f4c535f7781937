// mobb record convert: crowd records between JSON and HDF5 (include/mobb/crowd/record/record_file.h).
#include <iostream>

#include "cli.h"
#include "mobb/crowd/record/record_file.h"

namespace mobb::app {

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
            const crowd::RecordFile r = crowd::read_record_file(*from);
            if (!r.note.empty()) std::cerr << r.note << "\n";
            crowd::write_record_file(*to, r.record, r.summary_json, r.metrics_json);
            out << *to << ": " << r.record.tracks.size() << " agents, " << r.record.frames << " frames, "
                << r.record.choices.size() << " choice points\n";
        });
    });
}

}  // namespace mobb::app
