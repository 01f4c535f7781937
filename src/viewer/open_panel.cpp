// Opening clip files from inside the window: the Open panel lists the data folder's clip files (every
// extension load_clip reads: BVH, glTF, FBX, Collada, ...), and files dropped on the window (GLFW's drop
// callback fills ui.dropped) open the same way. Each opened file becomes a scene clip, offered at once by
// the Query panel's A and B lists.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <imgui.h>

#include "layout.h"
#include "mobb/io/load.h"
#include "panels.h"

namespace mobb::viewer {

namespace {

/// "reads .3d .3ds ... .zgl": the formats, for the panel's tooltip.
std::string extensions_text() {
    std::string out = "reads";
    for (const std::string& ext : io::clip_extensions()) out += " " + ext;
    return out;
}

void open_file(State& s, Ui& ui, const std::string& file) {
    try {
        const int k = add_clip_file(s, file);
        ui.open_status = "opened " + s.clips[std::size_t(k)].name + " as clip " + std::to_string(k);
    } catch (const std::exception& e) {
        ui.open_status = e.what();
        ui.panels.open = true;  // a dropped file that failed says why
    }
}

}  // namespace

std::vector<std::string> list_clip_files(const std::string& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    if (dir.empty()) return out;
    for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file(ec) && io::is_clip_file(it->path().string()))
            out.push_back(it->path().lexically_relative(dir).generic_string());
    std::sort(out.begin(), out.end());
    return out;
}

void open_dropped(State& s, Ui& ui) {
    for (const std::string& f : ui.dropped) open_file(s, ui, f);
    ui.dropped.clear();
}

void open_panel(State& s, Ui& ui) {
    ImGui::SetNextWindowSize(ImVec2(300, 240), ImGuiCond_FirstUseEver);
    if (!begin_panel(s, ui, &PanelsOpen::open)) return;
    const std::string dir = io::data_dir();
    if (!ui.data_listed) {
        ui.data_files = list_clip_files(dir);
        ui.data_listed = true;
    }
    if (dir.empty())
        ImGui::TextDisabled("no data folder (set MOBB_DATA)");
    else
        ImGui::TextDisabled("%zu clip files in the data folder", ui.data_files.size());
    if (ImGui::IsItemHovered() && !dir.empty()) ImGui::SetTooltip("%s", dir.c_str());
    ImGui::TextDisabled("click to open, or drop files here");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", extensions_text().c_str());
    char filter[128];
    std::snprintf(filter, sizeof filter, "%s", ui.open_filter.c_str());
    if (ImGui::InputTextWithHint("##filter", "filter", filter, sizeof filter)) ui.open_filter = filter;
    ImGui::SameLine();
    if (ImGui::Button("rescan")) ui.data_listed = false;
    ImGui::BeginChild("files", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() - 2), true);
    for (const std::string& f : ui.data_files) {
        if (!ui.open_filter.empty() && f.find(ui.open_filter) == std::string::npos) continue;
        if (ImGui::Selectable(f.c_str())) open_file(s, ui, (dir + '/').append(f));
    }
    ImGui::EndChild();
    if (!ui.open_status.empty()) ImGui::TextWrapped("%s", ui.open_status.c_str());
    ImGui::End();
}

}  // namespace mobb::viewer
