// The Crowd panel, for a recorded crowd (its playback and timeline stand in the Timeline strip): pick
// an agent and one of its choice points, list the candidates (accepted / rejected) and their
// queries, and open any of them in the trace debugger.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <imgui.h>

#include "crowd_view.h"
#include "layout.h"
#include "panels.h"
#include "widgets.h"

namespace mobb::viewer {

namespace {

/// The choice-point list's share of the panel's room below it when a choice point's candidates are
/// listed under it (the candidates take the rest); the least either list keeps is kLeastRows rows.
constexpr float kChoiceShare = 0.4f;
constexpr float kLeastRows = 3.0f;

/// A bordered list's height for `rows` rows: the rows and the child window's padding above and below.
float list_height(float rows) {
    return rows * ImGui::GetTextLineHeightWithSpacing() + 2.0f * ImGui::GetStyle().WindowPadding.y;
}

/// The room the lists have: what is left of the panel above the status line under them.
float room_for_lists(const Ui& ui) {
    float room = ImGui::GetContentRegionAvail().y;
    if (!ui.status.empty())
        room -= ImGui::CalcTextSize(ui.status.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x).y +
                ImGui::GetStyle().ItemSpacing.y;
    return room;
}

/// What a query was against, in words: another agent's clip (committed, or reserved to stop it), its
/// held ground, or a wall or an obstacle.
std::string query_target(const CrowdView& v, const crowd::CandidateQuery& q) {
    if (q.agent < 0) return "wall or obstacle " + std::to_string(q.solid);
    if (q.piece < 0) return "agent " + std::to_string(q.agent) + ", held ground";
    try {
        const auto c = query_clip(v, q);
        return "agent " + std::to_string(q.agent) + ", clip " + std::to_string(c->clip) +
               (q.piece > 0 ? " (its escape)" : "");
    } catch (const std::out_of_range&) {
        return "agent " + std::to_string(q.agent) + ", unknown clip";
    }
}

/// The camera presets, named as in the Scene panel; the tooltips give their keys.
void view_buttons(Ui& ui) {
    if (ImGui::Button("top")) ui.request_view = ViewPreset::Top;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("top view (T)");
    ImGui::SameLine();
    if (ImGui::Button("side")) ui.request_view = ViewPreset::Side;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("side view (S)");
}

/// Selects as select_choice does; a file that cannot be read leaves the choice point unselected and
/// says why in the status line.
void select(State& s, Ui& ui, int agent, int choice) {
    try {
        select_choice(s, agent, choice);
    } catch (const std::runtime_error& e) {
        select_choice(s, agent, -1);
        ui.status = e.what();
    }
}

/// The agent chosen, what its skeletons lack, and its choice points (those in the frames at hand of a
/// record read in windows), in a list as tall as the panel allows (a share of it once a choice point's
/// candidates are listed); choosing one moves the cursor to it.
void choice_list(State& s, Ui& ui) {
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record();
    int agent = v.agent;
    if (ImGui::SliderInt("agent", &agent, 0, std::max(0, v.agents - 1))) select(s, ui, agent, -1);
    if (!v.graph)
        ImGui::TextWrapped("graph not loaded (%s): no skeletons, candidates listed only", v.graph_error.c_str());
    else if (!skeleton_problem(v).empty())
        ImGui::TextWrapped("skeletons not shown: %s", skeleton_problem(v).c_str());
    if (v.whole())
        ImGui::TextColored(imvec(render::clip_color(v.agent)), "agent %d choice points:", v.agent);
    else
        ImGui::TextColored(imvec(render::clip_color(v.agent)), "agent %d choice points, %.1f to %.1f s:", v.agent,
                           double(v.window.first) * r.dt, double(v.window.last) * r.dt);
    std::vector<crowd::ChoiceSummary> none;
    const std::vector<crowd::ChoiceSummary>* listed = &none;
    try {
        listed = &agent_choices(v, v.agent);
    } catch (const std::runtime_error& e) {
        ui.status = e.what();
    }
    const std::vector<crowd::ChoiceSummary>& choices = *listed;
    // A record without candidates (an HDF5 one unless recorded with them) lists none: no count to show.
    const bool counted = v.reader->has_candidates();
    if (!counted) ImGui::TextWrapped("candidates not recorded (mobb crowd --record-candidates keeps them)");
    const float room = room_for_lists(ui);
    const float height = v.choice < 0 ? room
                                      : std::min(list_height(float(choices.size())),
                                                 std::max(list_height(kLeastRows), kChoiceShare * room));
    // A row wider than the panel scrolls sideways, and hovering it shows it whole.
    ImGui::BeginChild("choices", ImVec2(0, std::max(height, list_height(kLeastRows))), true,
                      ImGuiWindowFlags_HorizontalScrollbar);
    for (const crowd::ChoiceSummary& listed_choice : choices) {
        const crowd::ChoicePoint& c = listed_choice.point;
        const int k = int(listed_choice.row);
        char label[96];
        const std::string outcome = c.outcome == "candidate" ? "" : " (" + c.outcome + ")";
        const std::size_t n = listed_choice.candidates;
        const std::string tested = counted ? ", " + std::to_string(n) + (n == 1 ? " candidate" : " candidates") : "";
        std::snprintf(label, sizeof label, "%.2f s: clip %d%s%s##%d", double(c.frame) * r.dt, c.taken, tested.c_str(),
                      outcome.c_str(), k);
        if (ImGui::Selectable(label, v.choice == k)) {
            select(s, ui, v.agent, v.choice == k ? -1 : k);
            if (v.choice >= 0) s.scene.cursor = double(c.frame) * r.dt;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(label, std::strcspn(label, "#")).c_str());
    }
    ImGui::EndChild();
}

/// One candidate of the selected choice point, coloured taken / clear / rejected, unfolding into its
/// queries in the order the crowd ran them (other agent, its clip, the answer); clicking one opens it
/// in the trace debugger.
void candidate_row(State& s, Ui& ui, const crowd::ChoicePoint& c, int k) {
    CrowdView& v = *s.crowd;
    const crowd::Candidate& cand = c.candidates[std::size_t(k)];
    const bool taken = cand.clip == c.taken;
    const bool ok = !cand.leaves_world && !cand.meets_solid && cand.hits == 0 && !cand.crowded;
    const glm::vec3 col = taken ? glm::vec3(0.95f, 0.85f, 0.2f)
                          : ok  ? glm::vec3(0.25f, 0.8f, 0.3f)
                                : glm::vec3(0.9f, 0.2f, 0.2f);
    // Why it was refused, short enough for the row; hovering it gives the whole reason.
    const char* why = cand.leaves_world  ? " (off world)"
                      : cand.meets_solid ? " (solid)"
                      : cand.crowded     ? " (too close)"
                                         : "";
    const char* why_long = cand.leaves_world
                               ? "Its root goes farther outside the world than where it starts (random mode)."
                           : cand.meets_solid ? "It meets a solid: a wall or an obstacle."
                           : cand.crowded     ? "Would stop too close to where another agent stands (the standing gap)."
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
        std::snprintf(label, sizeof label, "vs %s: %s###q%d_%zu", query_target(v, q).c_str(), q.hit ? "hit" : "clear",
                      k, j);
        const bool shown = v.opened_candidate == k && v.opened_query == int(j);
        if (ImGui::Selectable(label, shown) && v.graph && open_candidate_query(s, k, int(j), &ui.status))
            for (bool PanelsOpen::*p : {&PanelsOpen::query, &PanelsOpen::trace, &PanelsOpen::recursion})
                open_when_used(ui, p);
    }
    ImGui::TreePop();
}

/// The selected choice point: its counts, who gave way, the plan looked ahead, and its candidates.
void choice_details(State& s, Ui& ui) {
    const crowd::ChoicePoint& c = s.crowd->selected;
    ImGui::Text("%llu queries, %llu 2D tests, %llu pruned", static_cast<unsigned long long>(c.queries),
                static_cast<unsigned long long>(c.tests2d), static_cast<unsigned long long>(c.pruned));
    for (const crowd::ReroutedPlan& rr : c.reroutes) ImGui::TextWrapped("agent %d gave way (right of way)", rr.agent);
    if (!c.intended.empty()) {
        std::string plan = "plan: clip " + std::to_string(c.taken);
        for (const crowd::FramedClip& e : c.intended) plan += ", " + std::to_string(e.clip);
        ImGui::TextWrapped("%s (looked ahead)", plan.c_str());
    }
    // The rest of the panel: a fallback may list dozens of candidates, which scroll.
    // Its rows and their queries run wider than a column: they scroll sideways.
    ImGui::BeginChild("candidates", ImVec2(0, std::max(room_for_lists(ui), list_height(kLeastRows))), true,
                      ImGuiWindowFlags_HorizontalScrollbar);
    for (std::size_t k = 0; k < c.candidates.size(); ++k) candidate_row(s, ui, c, int(k));
    ImGui::EndChild();
}

}  // namespace

void crowd_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::crowd)) return;
    view_buttons(ui);
    choice_list(s, ui);
    if (s.crowd->choice >= 0) choice_details(s, ui);
    if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::End();
}

}  // namespace mobb::viewer
