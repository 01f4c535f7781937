// mobb tree FILE: levels of a clip's tree, box sizes, and whether every sample is contained.
#include <iomanip>

#include <nlohmann/json.hpp>

#include "cli.h"

namespace mobb::app {

namespace {

void print_text(std::ostream& out, const Tree& tree, const std::vector<LevelStats>& levels, bool contained) {
    out << "tree: " << to_string(tree.options().type) << ", n_min " << tree.options().n_min << ", "
        << tree.path().size() << " samples, " << tree.nodes().size() << " nodes, depth " << tree.depth() << "\n";
    out << "level  nodes  2d  3d   mean area (m^2)  area/disks  mean volume (m^2 s)  volume/cylinders\n";
    for (const LevelStats& l : levels) {
        out << std::setw(5) << l.level << std::setw(7) << l.nodes << std::setw(4) << l.box2 << std::setw(4) << l.box3
            << std::fixed << std::setprecision(4);
        if (l.box2)
            out << std::setw(18) << l.mean_area << std::setw(12) << l.area_ratio;
        else
            out << std::setw(18) << "-" << std::setw(12) << "-";
        out << std::setw(21) << l.mean_volume << std::setw(18) << l.volume_ratio << "\n";
    }
    out << "all sample cylinders contained: " << (contained ? "yes" : "NO") << "\n";
}

nlohmann::json to_json(const Tree& tree, const std::vector<LevelStats>& levels, bool contained) {
    nlohmann::json j;
    j["tree"] = to_string(tree.options().type);
    j["nmin"] = tree.options().n_min;
    j["samples"] = tree.path().size();
    j["nodes"] = tree.nodes().size();
    j["depth"] = tree.depth();
    j["contained"] = contained;
    for (const LevelStats& l : levels)
        j["levels"].push_back({{"level", l.level},
                               {"nodes", l.nodes},
                               {"box2d", l.box2},
                               {"box3d", l.box3},
                               {"mean_area", l.mean_area},
                               {"area_ratio", l.area_ratio},
                               {"mean_volume", l.mean_volume},
                               {"volume_ratio", l.volume_ratio}});
    return j;
}

}  // namespace

void add_tree(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("tree", "Build a clip's tree and report its levels and fit");
    auto file = std::make_shared<std::string>();
    auto load = std::make_shared<LoadArgs>();
    auto tree_args = std::make_shared<TreeArgs>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "BVH or glTF/GLB file")->required();
    load->add_to(*cmd);
    tree_args->add_to(*cmd, false);
    cmd->add_flag("--json", *json, "Print JSON instead of a table");
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            const Tree tree = Tree::build(load_reported(*file, load->options()).path, tree_args->options());
            const auto levels = level_stats(tree);
            const bool contained = all_samples_contained(tree);
            if (*json)
                out << to_json(tree, levels, contained).dump(2) << "\n";
            else
                print_text(out, tree, levels, contained);
        });
    });
}

}  // namespace mobb::app
