#include "panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "crowd_view.h"
#include "mobb/core/angle.h"
#include "shortcuts.h"

namespace mobb::viewer {

namespace {

ImVec4 imvec(const glm::vec3& c) { return {c.r, c.g, c.b, 1.0f}; }

int max_level(const State& s) {
    int depth = 1;
    for (const LoadedClip& c : s.clips) depth = std::max(depth, c.tree->depth());
    return depth - 1;
}

double max_time(const State& s) {
    double t = 1.0;
    for (std::size_t k = 0; k < s.clips.size(); ++k)
        t = std::max(t, s.places[k].t0 + s.clips[k].tree->path().duration());
    return t;
}

bool drag(const char* label, double* v, float speed, double lo, double hi, const char* format) {
    return ImGui::DragScalar(label, ImGuiDataType_Double, v, speed, &lo, &hi, format);
}

/// Saves the scene (placements and camera included) to ui.save_path; the outcome goes to ui.status.
void save_to_path(State& s, Ui& ui) {
    try {
        sync_scene(s);
        save_scene(s.scene, ui.save_path);
        ui.status = "saved " + ui.save_path;
    } catch (const std::exception& e) {
        ui.status = e.what();
    }
}

/// The disk and box colourings (colour maps with a colour bar); a box colouring shows the boxes.
void colouring_combos(render::Layers& l) {
    const char* disks[render::kDiskColours];
    const char* boxes[render::kBoxColours];
    for (int k = 0; k < render::kDiskColours; ++k) disks[k] = to_string(render::DiskColour(k));
    for (int k = 0; k < render::kBoxColours; ++k) boxes[k] = to_string(render::BoxColour(k));
    int d = int(l.disk_colour), b = int(l.box_colour);
    if (ImGui::Combo("disks by", &d, disks, render::kDiskColours)) l.disk_colour = render::DiskColour(d);
    if (ImGui::Combo("boxes by", &b, boxes, render::kBoxColours)) {
        l.box_colour = render::BoxColour(b);
        if (l.box_colour != render::BoxColour::Level) l.boxes = true;
    }
}

void scene_panel(State& s, Ui& ui) {
    if (!ui.panels.scene) return;
    ImGui::SetNextWindowPos(ImVec2(8, ui.menu_height + 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Scene", &ui.panels.scene)) return ImGui::End();
    render::Layers& l = s.scene.layers;
    ImGui::Checkbox("grid", &l.grid);
    ImGui::SameLine();
    ImGui::Checkbox("labels", &l.labels);
    ImGui::Checkbox("disks", &l.disks);
    ImGui::SameLine();
    ImGui::Checkbox("translucent", &l.disks_translucent);
    ImGui::Checkbox("boxes", &l.boxes);
    ImGui::SameLine();
    ImGui::Checkbox("faces", &l.box_faces);
    ImGui::SameLine();
    ImGui::Checkbox("all", &l.all_levels);
    ImGui::SliderInt("level", &l.level, 0, max_level(s));
    ImGui::Checkbox("cursor", &l.cursor);
    ImGui::SameLine();
    ImGui::Checkbox("skeletons", &l.skeletons);
    ImGui::SameLine();
    ImGui::Checkbox("trace", &l.trace);
    colouring_combos(l);
    drag("time", &s.scene.cursor, 0.01f, 0.0, max_time(s), "%.2f s");
    drag("window", &s.scene.window, 0.05f, 0.0, max_time(s), s.scene.window > 0 ? "+-%.2f s" : "all time");
    drag("m per s", &s.scene.time_scale, 0.01f, 0.05, 20.0, "%.2f");
    drag("skeleton", &s.scene.skeleton_scale, 0.01f, 0.05, 5.0, "%.2f x");
    if (ImGui::Button("frame all (F)")) ui.request_frame_all = true;
    ImGui::SameLine();
    if (ImGui::Button("top")) ui.request_view = 1;
    ImGui::SameLine();
    if (ImGui::Button("side")) ui.request_view = 2;
    ImGui::SameLine();
    if (ImGui::Button("?")) ui.show_help = !ui.show_help;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("shortcuts (F1)");
    char path[256];
    std::snprintf(path, sizeof path, "%s", ui.save_path.c_str());
    if (ImGui::InputText("##path", path, sizeof path)) ui.save_path = path;
    ImGui::SameLine();
    if (ImGui::Button("save")) save_to_path(s, ui);
    if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::End();
}

bool clip_combo(const char* label, int* index, const State& s) {
    const char* preview = *index >= 0 && *index < int(s.clips.size()) ? s.clips[std::size_t(*index)].name.c_str() : "-";
    bool changed = false;
    if (ImGui::BeginCombo(label, preview)) {
        for (int k = 0; k < int(s.clips.size()); ++k) {
            ImGui::PushID(k);
            if (ImGui::Selectable(s.clips[std::size_t(k)].name.c_str(), k == *index)) {
                *index = k;
                changed = true;
            }
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool placement_fields(const char* id, Placement& p) {
    ImGui::PushID(id);
    double xy[2] = {p.x, p.y}, turn[2] = {degrees(p.theta), p.t0};
    const double lo = -1e4, hi = 1e4;
    bool changed = false;
    if (ImGui::DragScalarN("x y (m)", ImGuiDataType_Double, xy, 2, 0.01f, &lo, &hi, "%.2f")) {
        p.x = xy[0], p.y = xy[1];
        changed = true;
    }
    if (ImGui::DragScalarN("deg t0 (s)", ImGuiDataType_Double, turn, 2, 0.05f, &lo, &hi, "%.2f")) {
        p.theta = radians(turn[0]), p.t0 = turn[1];
        changed = true;
    }
    ImGui::PopID();
    return changed;
}

/// A plot's horizontal position under the mouse, 0..1 over the last item.
/// The right-hand column (Query above Trace).
constexpr float kRightWidth = 330.0f, kQueryHeight = 420.0f;

float plot_fraction() {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    return std::clamp((ImGui::GetIO().MousePos.x - lo.x) / std::max(1.0f, hi.x - lo.x), 0.0f, 1.0f);
}

/// One more series drawn over the last PlotLines item, on its scale [lo, hi].
void plot_overlay(const std::vector<float>& values, float lo, float hi, ImU32 colour) {
    if (values.size() < 2 || !(hi > lo)) return;
    const ImGuiStyle& st = ImGui::GetStyle();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    const float x0 = a.x + st.FramePadding.x, x1 = b.x - st.FramePadding.x;
    const float y0 = a.y + st.FramePadding.y, y1 = b.y - st.FramePadding.y;
    std::vector<ImVec2> line;
    for (std::size_t k = 0; k < values.size(); ++k)
        line.emplace_back(x0 + (x1 - x0) * float(k) / float(values.size() - 1),
                          y1 - (y1 - y0) * std::clamp((values[k] - lo) / (hi - lo), 0.0f, 1.0f));
    ImGui::GetWindowDrawList()->AddPolyline(line.data(), int(line.size()), colour, 0, 1.5f);
}

/// A vertical line at time t on the last plot item spanning [t0, t1] (the time cursor).
void time_line(double t, double t0, double t1, ImU32 colour) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    if (!(t1 > t0) || t < t0 || t > t1) return;
    const float x = lo.x + float((t - t0) / (t1 - t0)) * (hi.x - lo.x);
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), colour);
}

// The distance between the query's clips A and B over time (ImGui's PlotLines, metres) against
// r_a + r_b (red): where the distance dips under the red line the disks overlap. Clicking moves the
// time cursor there.
void distance_plot(State& s) {
    if (s.clearance.empty()) return ImGui::TextDisabled("the clips never meet in time");
    const Path& pa = s.clips[std::size_t(s.scene.query_a)].tree->path();
    const Path& pb = s.clips[std::size_t(s.scene.query_b)].tree->path();
    std::vector<float> distance, radii;
    float high = 0;
    std::size_t least = 0;
    for (std::size_t k = 0; k < s.clearance.size(); ++k) {
        const ClearanceSample& c = s.clearance[k];
        const double r = pa.samples[std::size_t(c.i)].r + pb.samples[std::size_t(c.j)].r;
        distance.push_back(float(c.gap + r));
        radii.push_back(float(r));
        high = std::max({high, distance.back(), radii.back()});
        if (c.gap < s.clearance[least].gap) least = k;
    }
    high *= 1.05f;
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "closest %.2f m at %.2f s", double(distance[least]), s.clearance[least].t);
    ImGui::TextUnformatted("distance A-B against r_a + r_b (red), m");
    ImGui::PlotLines("##distance", distance.data(), int(distance.size()), 0, overlay, 0.0f, high,
                     ImVec2(ImGui::GetContentRegionAvail().x, 64));
    plot_overlay(radii, 0.0f, high, IM_COL32(230, 60, 60, 220));
    time_line(s.scene.cursor, s.clearance.front().t, s.clearance.back().t, IM_COL32(240, 200, 80, 220));
    if (ImGui::IsItemClicked())
        s.scene.cursor =
            s.clearance[std::min(s.clearance.size() - 1, std::size_t(plot_fraction() * float(s.clearance.size())))].t;
}

void query_panel(State& s, Ui& ui) {
    if (!ui.panels.query) return;
    ImGui::SetNextWindowPos(ImVec2(float(ui.window_size.x) - kRightWidth - 8, ui.menu_height + 8),
                            ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kRightWidth, kQueryHeight), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Query", &ui.panels.query)) return ImGui::End();
    bool rerun = clip_combo("A", &s.scene.query_a, s);
    rerun |= clip_combo("B", &s.scene.query_b, s);
    const int a = s.scene.query_a, b = s.scene.query_b, n = int(s.clips.size());
    if (a >= 0 && a < n) {
        ImGui::TextColored(imvec(render::clip_color(a)), "A: %s", s.clips[std::size_t(a)].name.c_str());
        rerun |= placement_fields("pa", s.places[std::size_t(a)]);
    }
    if (b >= 0 && b < n) {
        ImGui::TextColored(imvec(render::clip_color(b)), "B: %s", s.clips[std::size_t(b)].name.c_str());
        rerun |= placement_fields("pb", s.places[std::size_t(b)]);
    }
    const auto type_label = [](void*, int k, const char** out) {
        *out = kTreeTypes[k].label;
        return true;
    };
    int type = int(s.scene.tree.type);
    bool rebuild = ImGui::Combo("tree", &type, type_label, nullptr, kTreeTypeCount);
    rebuild |= ImGui::SliderInt("n_min", &s.scene.tree.n_min, 1, 64);
    if (rebuild) {
        s.scene.tree.type = TreeType(type);
        s.scene.tree.n_min = std::max(1, s.scene.tree.n_min);
        rebuild_trees(s);
    } else if (rerun || ImGui::Button("run query")) {
        run_query(s);
    }
    if (s.queried) {
        ImGui::TextColored(s.answer ? ImVec4(0.9f, 0.1f, 0.1f, 1) : ImVec4(0.1f, 0.6f, 0.2f, 1), "%s",
                           s.answer ? "collide: yes" : "collide: no");
        if (s.answer) ImGui::Text("hit: A sample %lld, B sample %lld", (long long)s.hit.a, (long long)s.hit.b);
        ImGui::Text("2D tests %llu  3D tests %llu", (unsigned long long)s.stats.tests2d,
                    (unsigned long long)s.stats.tests3d);
        ImGui::Text("sample tests %llu  events %zu", (unsigned long long)s.stats.samples, s.trace.size());
        distance_plot(s);
    } else {
        ImGui::TextDisabled("choose two different clips");
    }
    ImGui::End();
}

const char* short_name(TraceTest t) { return to_string(t); }

void trace_panel(State& s, Ui& ui) {
    if (!ui.panels.trace) return;
    const float top = ui.menu_height + kQueryHeight + 16;
    ImGui::SetNextWindowPos(ImVec2(float(ui.window_size.x) - kRightWidth - 8, top), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kRightWidth, std::max(160.0f, float(ui.window_size.y) - top - 8)),
                             ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Trace", &ui.panels.trace)) return ImGui::End();
    const int last = int(s.trace.size()) - 1;
    const int step = shown_step(s);
    if (ImGui::Button("|<")) go_to_step(s, ui, 0);
    ImGui::SameLine();
    if (ImGui::Button("<")) go_to_step(s, ui, step - 1);
    ImGui::SameLine();
    if (ImGui::Button(ui.playing ? "pause" : "play")) ui.playing = !ui.playing;
    ImGui::SameLine();
    if (ImGui::Button(">")) go_to_step(s, ui, step + 1);
    ImGui::SameLine();
    if (ImGui::Button(">|")) go_to_step(s, ui, last);
    ImGui::SliderFloat("steps/s", &ui.rate, 0.5f, 60.0f, "%.1f");
    int k = step;
    if (last >= 0 && ImGui::SliderInt("step", &k, 0, last)) go_to_step(s, ui, k);
    outcome_strip(s, ui);
    ImGui::Checkbox("cursor follows step", &ui.follow);
    ImGui::Separator();
    ImGui::BeginChild("events");
    ImGuiListClipper clipper;
    clipper.Begin(int(s.trace.size()));
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const TraceEvent& e = s.trace[std::size_t(i)];
            char line[128];
            std::snprintf(line, sizeof line, "%4d %-7s A%-4d B%-4d %s", i, short_name(e.test), int(e.node_a),
                          int(e.node_b), to_string(e.outcome));
            ImGui::PushStyleColor(ImGuiCol_Text, imvec(render::outcome_color(e.outcome) * 0.8f));
            if (ImGui::Selectable(line, i == step)) go_to_step(s, ui, i);
            ImGui::PopStyleColor();
        }
    }
    if (ui.scroll_to_step && step >= 0) {
        ImGui::SetScrollY(float(step) * ImGui::GetTextLineHeightWithSpacing() - ImGui::GetWindowHeight() * 0.5f);
        ui.scroll_to_step = false;
    }
    ImGui::EndChild();
    ImGui::End();
}

void update_fit(const State& s, FitTable& fit) {
    if (fit.clip == -1 && !s.clips.empty()) fit.clip = std::max(0, s.scene.query_a);
    if (fit.clip < 0 || fit.clip >= int(s.clips.size())) return;
    if (fit.revision == s.revision && fit.n_min == s.scene.tree.n_min && !fit.mobb.empty()) return;
    const Path& path = s.clips[std::size_t(fit.clip)].tree->path();
    TreeOptions o;
    o.n_min = s.scene.tree.n_min;
    o.type = TreeType::Mobb;
    fit.mobb = level_stats(Tree::build(path, o));
    o.type = TreeType::Umobb;
    fit.umobb = level_stats(Tree::build(path, o));
    o.type = TreeType::Mobb;
    o.fit = AxisFit::Pca;
    fit.pca = level_stats(Tree::build(path, o));
    fit.n_min = s.scene.tree.n_min;
    fit.revision = s.revision;
}

/// Tightness per level (ImGui's PlotLines): MOBB area ratio (white), UMOBB volume ratio (blue), PCA
/// area ratio (orange); lower is tighter. Clicking a level shows its boxes.
void tightness_plot(State& s, const FitTable& fit) {
    const std::size_t rows = std::min({fit.mobb.size(), fit.umobb.size(), fit.pca.size()});
    if (rows < 2) return;
    std::vector<float> m, u, p;
    float high = 1.0f;
    for (std::size_t r = 0; r < rows; ++r) {
        m.push_back(float(fit.mobb[r].area_ratio));
        u.push_back(float(fit.umobb[r].volume_ratio));
        p.push_back(float(fit.pca[r].area_ratio));
        high = std::max({high, m.back(), u.back(), p.back()});
    }
    ImGui::TextColored(ImVec4(0.85f, 0.85f, 0.85f, 1), "MOBB");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.4f, 0.6f, 1.0f, 1), "UMOBB");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1), "PCA");
    ImGui::SameLine();
    ImGui::TextDisabled("by level, 1 = perfect (bottom)");
    ImGui::PushStyleColor(ImGuiCol_PlotLines, ImVec4(0.85f, 0.85f, 0.85f, 1));
    ImGui::PlotLines("##tightness", m.data(), int(m.size()), 0, nullptr, 1.0f, high * 1.05f,
                     ImVec2(ImGui::GetContentRegionAvail().x, 48));
    ImGui::PopStyleColor();
    plot_overlay(u, 1.0f, high * 1.05f, IM_COL32(100, 150, 255, 255));
    plot_overlay(p, 1.0f, high * 1.05f, IM_COL32(255, 150, 50, 255));
    if (ImGui::IsItemClicked())
        s.scene.layers.level = std::min(int(rows) - 1, int(plot_fraction() * float(rows - 1) + 0.5f));
}

void fit_panel(State& s, Ui& ui) {
    if (!ui.panels.fit) return;
    ImGui::SetNextWindowPos(ImVec2(8, float(ui.window_size.y) - 8.0f), ImGuiCond_FirstUseEver, ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(440, 0), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Tree fit", &ui.panels.fit)) return ImGui::End();
    if (clip_combo("clip", &ui.fit.clip, s)) ui.fit.mobb.clear();
    update_fit(s, ui.fit);
    ImGui::TextDisabled("tight = box / covered (area, volume); 1 is perfect");
    const ImGuiTableFlags flags =
        ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    const float rows_shown = float(std::min<std::size_t>(ui.fit.mobb.size(), 5)) + 1.3f;
    if (ImGui::BeginTable("fit", 7, flags, ImVec2(0, rows_shown * ImGui::GetTextLineHeightWithSpacing() + 4))) {
        for (const char* h : {"lvl", "nodes", "MOBB m2", "tight", "UMOBB m2s", "tight", "PCA tight"})
            ImGui::TableSetupColumn(h);
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableHeadersRow();
        const std::size_t rows = std::min({ui.fit.mobb.size(), ui.fit.umobb.size(), ui.fit.pca.size()});
        for (std::size_t r = 0; r < rows; ++r) {
            const LevelStats &m = ui.fit.mobb[r], &u = ui.fit.umobb[r], &p = ui.fit.pca[r];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(imvec(render::level_color(m.level)), "%d", m.level);
            ImGui::TableNextColumn();
            ImGui::Text("%d", m.nodes);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", m.mean_area);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", m.area_ratio);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", u.mean_volume);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", u.volume_ratio);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", p.area_ratio);
        }
        ImGui::EndTable();
    }
    tightness_plot(s, ui.fit);
    ImGui::End();
}

/// What a query was against, in words: another agent's clip (committed, or reserved to stop it), its
/// held ground, or a wall or an obstacle.
std::string query_target(const crowd::Record& r, const crowd::CandidateQuery& q) {
    if (q.agent < 0) return "wall or obstacle " + std::to_string(q.commit);
    if (q.piece < 0) return "agent " + std::to_string(q.agent) + ", held ground";
    try {
        const auto c = crowd::query_clip(r, q);
        return "agent " + std::to_string(q.agent) + ", clip " + std::to_string(c->clip) +
               (q.piece > 0 ? " (its escape)" : "");
    } catch (const std::out_of_range&) {
        return "agent " + std::to_string(q.agent) + ", unknown clip";
    }
}

/// The run as a strip: fallbacks (orange, upper half) and frames with contacts (red, lower half) at their
/// time, the cursor in white. Hover names the nearest mark; a click jumps to it (or to the time clicked),
/// dragging scrubs.
void timeline_strip(State& s) {
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record;
    const float w = std::max(ImGui::GetContentRegionAvail().x, 50.0f), h = 18.0f;
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("timeline", ImVec2(w, h));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(38, 38, 44, 255));
    const double frames = double(std::max<std::int64_t>(1, r.frames));
    auto x_of = [&](double f) { return p0.x + w * float(f / frames); };
    for (const TimelineMark& m : v.marks) {
        const float x = x_of(double(m.frame));
        const bool fallback = m.kind == TimelineMark::Fallback;
        draw->AddLine(ImVec2(x, fallback ? p0.y : p0.y + h / 2), ImVec2(x, fallback ? p0.y + h / 2 : p0.y + h),
                      fallback ? IM_COL32(255, 160, 40, 255) : IM_COL32(235, 40, 40, 255));
    }
    const float cx = x_of(s.scene.cursor / r.dt);
    draw->AddLine(ImVec2(cx, p0.y), ImVec2(cx, p0.y + h), IM_COL32(255, 255, 255, 255), 2.0f);
    if (!ImGui::IsItemHovered() && !ImGui::IsItemActive()) return;
    const auto frame = std::int64_t((ImGui::GetIO().MousePos.x - p0.x) / w * float(frames));
    const TimelineMark* near = nearest_mark(v.marks, frame, std::int64_t(4.0 / w * frames) + 1);
    if (near && near->kind == TimelineMark::Fallback)
        ImGui::SetTooltip("fallback: agent %d at %.2f s", near->agent, double(near->frame) * r.dt);
    else if (near)
        ImGui::SetTooltip("%d agent pairs in contact at %.2f s", near->count, double(near->frame) * r.dt);
    if (ImGui::IsItemClicked() && near)
        jump_to(s, *near);
    else if (ImGui::IsItemActive())
        s.scene.cursor = std::clamp(double(frame), 0.0, frames) * r.dt;
}

/// Fallbacks and agent pairs in contact per second of the run (ImGui's PlotHistogram); a click moves the
/// time cursor there.
void events_over_time(State& s) {
    if (s.crowd->marks.empty()) return;  // nothing to plot: the counts below say so
    const crowd::Record& r = s.crowd->record;
    const double seconds = double(r.frames) * r.dt;
    const int bins = std::clamp(int(std::ceil(seconds)), 1, 600);
    std::vector<float> fallbacks(std::size_t(bins), 0.0f), contacts(std::size_t(bins), 0.0f);
    for (const TimelineMark& m : s.crowd->marks) {
        const auto b = std::size_t(std::clamp(int(double(m.frame) * r.dt / seconds * bins), 0, bins - 1));
        if (m.kind == TimelineMark::Fallback)
            fallbacks[b] += 1.0f;
        else
            contacts[b] += float(m.count);
    }
    const float w = ImGui::GetContentRegionAvail().x;
    const auto plot = [&](const char* id, const std::vector<float>& v, ImVec4 colour, const char* what) {
        const float high = std::max(1.0f, *std::max_element(v.begin(), v.end()));
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "%s per second (max %.0f)", what, double(high));
        ImGui::PushStyleColor(ImGuiCol_PlotHistogram, colour);
        ImGui::PlotHistogram(id, v.data(), int(v.size()), 0, overlay, 0.0f, high, ImVec2(w, 30));
        ImGui::PopStyleColor();
        time_line(s.scene.cursor, 0.0, seconds, IM_COL32(255, 255, 255, 200));
        if (ImGui::IsItemClicked()) s.scene.cursor = double(plot_fraction()) * seconds;
    };
    plot("##fallbacks", fallbacks, ImVec4(1.0f, 0.63f, 0.16f, 1.0f), "fallbacks");
    plot("##contacts", contacts, ImVec4(0.92f, 0.16f, 0.16f, 1.0f), "contact pairs");
}

/// One candidate of the selected choice point, coloured taken / clear / rejected, unfolding into its
/// queries in the order the crowd ran them (other agent, its clip, the answer); clicking one opens it
/// in the trace debugger.
void candidate_row(State& s, Ui& ui, const crowd::ChoicePoint& c, int k) {
    CrowdView& v = *s.crowd;
    const crowd::Candidate& cand = c.candidates[std::size_t(k)];
    const bool taken = cand.clip == c.taken;
    const bool ok = !cand.outside && cand.hits == 0 && !cand.crowded;
    const glm::vec3 col = taken ? glm::vec3(0.95f, 0.85f, 0.2f)
                          : ok  ? glm::vec3(0.25f, 0.8f, 0.3f)
                                : glm::vec3(0.9f, 0.2f, 0.2f);
    // Why it was refused, short enough for the row; hovering it gives the whole reason.
    const char* why = cand.outside ? " (wall)" : cand.crowded ? " (too close)" : "";
    const char* why_long = cand.outside   ? "Leaves the world (random mode) or meets a wall or an obstacle."
                           : cand.crowded ? "Would stop too close to where another agent stands (the standing gap)."
                                          : nullptr;
    char label[128];
    std::snprintf(label, sizeof label, "clip %d: %s%s, %d queries, %d hits###cand%d", cand.clip,
                  taken ? "taken"
                  : ok  ? "clear"
                        : "rejected",
                  why, cand.queries, cand.hits, k);
    ImGui::PushStyleColor(ImGuiCol_Text, imvec(col));
    // The candidate whose query is open stays unfolded.
    if (v.opened_candidate == k) ImGui::SetNextItemOpen(true, ImGuiCond_Always);
    const bool open = ImGui::TreeNodeEx(label, cand.against.empty() ? ImGuiTreeNodeFlags_Leaf : 0);
    ImGui::PopStyleColor();
    if (why_long && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", why_long);
    if (!open) return;
    for (std::size_t j = 0; j < cand.against.size(); ++j) {
        const crowd::CandidateQuery& q = cand.against[j];
        std::snprintf(label, sizeof label, "vs %s: %s###q%d_%zu", query_target(v.record, q).c_str(),
                      q.hit ? "hit" : "clear", k, j);
        const bool shown = v.opened_candidate == k && v.opened_query == int(j);
        if (ImGui::Selectable(label, shown) && v.graph) open_candidate_query(s, k, int(j), &ui.status);
    }
    ImGui::TreePop();
}

/// A recorded crowd: play the time cursor, pick an agent and one of its choice points, list the
/// candidates (accepted / rejected) and their queries, and open any of them in the trace debugger.
void crowd_panel(State& s, Ui& ui) {
    if (!s.crowd) return;
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record;
    // Bottom middle, between the tree-fit and trace panels, clear of the crowd seen from the default camera.
    if (!ui.panels.crowd) return;
    ImGui::SetNextWindowPos(ImVec2(456, float(ui.window_size.y - 8)), ImGuiCond_FirstUseEver, ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Crowd", &ui.panels.crowd)) return ImGui::End();
    if (!r.scenario.empty()) ImGui::Text("scenario %s", r.scenario.c_str());
    ImGui::Text("%d agents, %.1f s, %s, seed %llu", v.agents, double(r.frames) * r.dt, r.select.c_str(),
                static_cast<unsigned long long>(r.seed));
    if (ImGui::Button(v.playing ? "pause" : "play")) v.playing = !v.playing;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::SliderFloat("rate", &v.rate, 0.1f, 4.0f, "%.1f x");
    float t = float(s.scene.cursor);
    if (ImGui::SliderFloat("time", &t, 0.0f, float(double(r.frames) * r.dt), "%.2f s")) s.scene.cursor = double(t);
    timeline_strip(s);
    const auto count = [&](TimelineMark::Kind kind) {
        return std::count_if(v.marks.begin(), v.marks.end(), [&](const auto& m) { return m.kind == kind; });
    };
    events_over_time(s);
    ImGui::TextColored(ImVec4(1.0f, 0.63f, 0.16f, 1.0f), "%ld fallbacks", long(count(TimelineMark::Fallback)));
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.92f, 0.16f, 0.16f, 1.0f), "%ld contact frames", long(count(TimelineMark::Contact)));
    if (ImGui::Button("from above")) ui.request_view = 1;
    ImGui::SameLine();
    if (ImGui::Button("space-time")) ui.request_view = 2;
    int agent = v.agent;
    if (ImGui::SliderInt("agent", &agent, 0, std::max(0, v.agents - 1))) select_choice(s, agent, -1);
    if (!v.graph)
        ImGui::TextWrapped("graph not loaded (%s): no skeletons, candidates listed only", v.graph_error.c_str());
    else if (!skeleton_problem(v).empty())
        ImGui::TextWrapped("skeletons not shown: %s", skeleton_problem(v).c_str());
    ImGui::TextColored(imvec(render::clip_color(v.agent)), "agent %d choice points:", v.agent);
    const std::vector<int> choices = agent_choices(v, v.agent);
    ImGui::BeginChild("choices", ImVec2(0, 110), true);
    for (int k : choices) {
        const crowd::ChoicePoint& c = r.choices[std::size_t(k)];
        char label[96];
        const std::string outcome = c.outcome == "candidate" ? "" : " (" + c.outcome + ")";
        std::snprintf(label, sizeof label, "%.2f s: clip %d, %zu candidates%s##%d", double(c.frame) * r.dt, c.taken,
                      c.candidates.size(), outcome.c_str(), k);
        if (ImGui::Selectable(label, v.choice == k)) {
            select_choice(s, v.agent, v.choice == k ? -1 : k);
            if (v.choice >= 0) s.scene.cursor = double(c.frame) * r.dt;
        }
    }
    ImGui::EndChild();
    if (v.choice >= 0) {
        const crowd::ChoicePoint& c = r.choices[std::size_t(v.choice)];
        ImGui::Text("%llu queries, %llu 2D tests, %llu pruned", static_cast<unsigned long long>(c.queries),
                    static_cast<unsigned long long>(c.tests2d), static_cast<unsigned long long>(c.pruned));
        for (const crowd::ReroutedPlan& rr : c.reroutes)
            ImGui::TextWrapped("agent %d gave way (right of way)", rr.agent);
        if (!c.intended.empty()) {
            std::string plan = "plan: clip " + std::to_string(c.taken);
            for (const crowd::FramedClip& e : c.intended) plan += ", " + std::to_string(e.clip);
            ImGui::TextWrapped("%s (looked ahead)", plan.c_str());
        }
        // A scrolled list past 14 rows: a fallback may list dozens of candidates, the view stays visible.
        std::size_t rows = c.candidates.size();
        for (const crowd::Candidate& cand : c.candidates) rows += cand.against.size();
        const float height = float(std::min<std::size_t>(rows, 14)) * ImGui::GetTextLineHeightWithSpacing() + 8.0f;
        ImGui::BeginChild("candidates", ImVec2(0, height), true);
        for (std::size_t k = 0; k < c.candidates.size(); ++k) candidate_row(s, ui, c, int(k));
        ImGui::EndChild();
    }
    if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::End();
}

/// The main menu bar: File (open, save), View (every panel, the Shortcuts window).
void main_menu(State& s, Ui& ui) {
    if (!ImGui::BeginMainMenuBar()) return;
    ui.menu_height = ImGui::GetWindowSize().y;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "O")) ui.panels.open = true;
        if (ImGui::MenuItem("Save scene", nullptr, false, s.crowd == nullptr)) save_to_path(s, ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        for (const PanelInfo& p : panel_list())
            if (p.open != &PanelsOpen::crowd || s.crowd) ImGui::MenuItem(p.name, nullptr, &(ui.panels.*p.open));
        ImGui::Separator();
        ImGui::MenuItem("Shortcuts", "F1", &ui.show_help);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace

void go_to_step(State& s, Ui& ui, int k) {
    if (s.trace.empty()) return;
    k = std::clamp(k, 0, int(s.trace.size()) - 1);
    s.scene.step = k;
    ui.scroll_to_step = true;
    ui.reveal_step = true;
    if (!ui.follow) return;
    // The cursor goes to the middle of the time both nodes share (or node A's start when none).
    const TraceEvent& e = s.trace[std::size_t(k)];
    const int a = s.scene.query_a, b = s.scene.query_b;
    auto span = [&](int clip, std::int32_t node, double& t0, double& t1) {
        const Tree& tree = *s.clips[std::size_t(clip)].tree;
        if (node < 0 || node >= std::int32_t(tree.nodes().size())) return false;
        const Node& n = tree.nodes()[std::size_t(node)];
        t0 = sample_time(s.places[std::size_t(clip)], tree.path().dt, n.first);
        t1 = sample_time(s.places[std::size_t(clip)], tree.path().dt, n.end);
        return true;
    };
    double a0, a1, b0, b1;
    if (!span(a, e.node_a, a0, a1) || !span(b, e.node_b, b0, b1)) return;
    if (e.outcome == TraceOutcome::Hit && e.sample_a >= 0) {
        const Path& pa = s.clips[std::size_t(a)].tree->path();
        s.scene.cursor = sample_time(s.places[std::size_t(a)], pa.dt, e.sample_a) + 0.5 * pa.dt;
    } else {
        const double lo = std::max(a0, b0), hi = std::min(a1, b1);
        s.scene.cursor = lo < hi ? 0.5 * (lo + hi) : 0.5 * (a0 + a1);
    }
}

void update_playback(State& s, Ui& ui, double seconds) {
    update_crowd_playback(s, seconds);
    if (!ui.playing || s.trace.empty()) return;
    ui.play_clock += seconds * double(ui.rate);
    const int steps = int(ui.play_clock);
    if (steps <= 0) return;
    ui.play_clock -= steps;
    const int next = shown_step(s) + steps;
    if (next >= int(s.trace.size())) ui.playing = false;
    go_to_step(s, ui, next);
}

void apply_style() {
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.FramePadding = ImVec2(4, 2);
    style.ItemSpacing = ImVec2(6, 3);
    style.WindowRounding = 3;
    style.Alpha = 0.96f;
}

const std::vector<PanelInfo>& panel_list() {
    static const std::vector<PanelInfo> list = {
        {"Scene", &PanelsOpen::scene},         {"Query", &PanelsOpen::query},  {"Trace", &PanelsOpen::trace},
        {"Recursion", &PanelsOpen::recursion}, {"Tree fit", &PanelsOpen::fit}, {"Inspector", &PanelsOpen::inspector},
        {"Crowd", &PanelsOpen::crowd},         {"Open", &PanelsOpen::open},
    };
    return list;
}

void draw_panels(State& s, Ui& ui) {
    open_dropped(s, ui);
    main_menu(s, ui);
    scene_panel(s, ui);
    query_panel(s, ui);
    trace_panel(s, ui);
    recursion_panel(s, ui);
    fit_panel(s, ui);
    inspector_panel(s, ui);
    crowd_panel(s, ui);
    open_panel(s, ui);
    shortcuts_window(ui);
}

}  // namespace mobb::viewer
