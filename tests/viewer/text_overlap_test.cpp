// Text that never overlaps (issue 31 part 6): the default scene, a crowd record and the plots (the colour
// bars, the Crowd panel's histograms) rendered headless from 640 x 400 to 3840 x 2160, with and without the
// panels. The labels the renderer reports drawing must lie wholly in the image and in the 3D view's
// viewport, apart from one another and from every panel; and a pixel check holds the report to the image:
// whatever the labels add to it lies in the boxes reported.
#include <algorithm>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>

#include "crowd_view.h"
#include "headless.h"
#include "panels.h"
#include "render_test_util.h"
#include "scene.h"
#include "state.h"

namespace mobb::test {
namespace {

using viewer::ImageRect;
using viewer::Rect;
using viewer::State;

struct Size {
    int width, height;
};
const Size kSizes[] = {{640, 400}, {900, 600}, {1280, 720}, {1920, 1080}, {3840, 2160}};

bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

std::string describe(const ImageRect& r) {
    std::ostringstream out;
    out << "\"" << r.name << "\" at " << r.rect.x << "," << r.rect.y << " " << r.rect.width << "x" << r.rect.height;
    return out.str();
}

/// One line for each label cut by the image's edge, overlapping another label or under a panel.
std::vector<std::string> label_problems(const std::vector<ImageRect>& labels, const std::vector<ImageRect>& windows,
                                        Size size) {
    std::vector<std::string> out;
    for (std::size_t a = 0; a < labels.size(); ++a) {
        const Rect& r = labels[a].rect;
        if (r.x < 0 || r.y < 0 || r.x + r.width > float(size.width) || r.y + r.height > float(size.height))
            out.push_back(describe(labels[a]) + " is cut by the image's edge");
        for (std::size_t b = a + 1; b < labels.size(); ++b)
            if (overlap(r, labels[b].rect)) out.push_back(describe(labels[a]) + " overlaps " + describe(labels[b]));
        for (const ImageRect& w : windows)
            if (overlap(r, w.rect)) out.push_back(describe(labels[a]) + " is under the " + w.name + " panel");
    }
    return out;
}

std::size_t count_ending(const std::vector<ImageRect>& labels, const std::string& unit) {
    return std::size_t(std::count_if(labels.begin(), labels.end(), [&](const ImageRect& l) {
        return l.name.size() > unit.size() && l.name.compare(l.name.size() - unit.size(), unit.size(), unit) == 0;
    }));
}

bool has_time_title(const std::vector<ImageRect>& labels) {
    return std::any_of(labels.begin(), labels.end(), [](const ImageRect& l) { return l.name.rfind("time (", 0) == 0; });
}

/// The pixels the labels add (the image with them against the same without) all lie in the reported boxes.
void check_ink_in_boxes(State& s, Size size, const render::Image& with, const std::vector<ImageRect>& labels) {
    const bool before = s.scene.layers.labels;
    s.scene.layers.labels = false;
    const render::Image without = viewer::render_headless(s, {size.width, size.height, false});
    s.scene.layers.labels = before;
    int stray = 0, first_x = -1, first_y = -1;
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            const auto* a = with.at(x, y);
            const auto* b = without.at(x, y);
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) continue;
            const bool in_box = std::any_of(labels.begin(), labels.end(), [&](const ImageRect& l) {
                return float(x) >= l.rect.x - 1 && float(x) < l.rect.x + l.rect.width + 1 && float(y) >= l.rect.y - 1 &&
                       float(y) < l.rect.y + l.rect.height + 1;
            });
            if (!in_box && stray++ == 0) first_x = x, first_y = y;
        }
    EXPECT_EQ(stray, 0) << size.width << "x" << size.height << ": label ink outside every reported box, first at "
                        << first_x << "," << first_y;
}

/// Renders `s` at every size, without panels and with those `ui` gives (everything framed in the viewport
/// they leave), and checks the labels; `load` makes the state afresh for each size.
void check_sizes(const std::function<State()>& load, const std::function<viewer::Ui(State&)>& ui) {
    for (const Size size : kSizes) {
        const std::string at = std::to_string(size.width) + "x" + std::to_string(size.height);
        State s = load();
        viewer::frame_all(s, float(size.width) / float(size.height));
        std::vector<ImageRect> labels;
        const render::Image image =
            viewer::render_headless(s, {size.width, size.height, false, false, nullptr, nullptr, &labels});
        for (const std::string& p : label_problems(labels, {}, size)) ADD_FAILURE() << at << ": " << p;
        // The axes stay labelled: the time axis's title, some of its ticks and some metres.
        EXPECT_TRUE(has_time_title(labels)) << at;
        EXPECT_GE(count_ending(labels, " s"), 3u) << at;
        EXPECT_GE(count_ending(labels, " m"), 2u) << at;
        check_ink_in_boxes(s, size, image, labels);

        viewer::Ui start = ui(s);
        start.request_frame_all = true;
        std::vector<ImageRect> windows;
        labels.clear();
        viewer::render_headless(s, {size.width, size.height, true, false, &start, nullptr, &labels, &windows});
        EXPECT_FALSE(windows.empty()) << at;
        for (const std::string& p : label_problems(labels, windows, size)) ADD_FAILURE() << at << " with panels: " << p;
        EXPECT_GE(count_ending(labels, " m"), 2u) << at << " with panels";
    }
}

viewer::Ui default_ui(State& s) {
    viewer::Ui ui;
    ui.panels = viewer::default_panels(s);
    return ui;
}

TEST(TextOverlap, DefaultScene) {
    MOBB_NEEDS_MOCAP();
    const viewer::Scene scene = viewer::load_scene(std::string(MOBB_ASSET_SCENES) + "/default.json");
    check_sizes([&] { return viewer::load_state(scene, 16.0f / 9.0f); }, default_ui);
}

/// Both colour bars (disks by clearance, boxes by the query's tests) at the right edge, with the labels.
TEST(TextOverlap, DefaultSceneWithColourBars) {
    MOBB_NEEDS_MOCAP();
    const viewer::Scene scene = viewer::load_scene(std::string(MOBB_ASSET_SCENES) + "/default.json");
    check_sizes(
        [&] {
            State s = viewer::load_state(scene, 16.0f / 9.0f);
            s.scene.layers.disk_colour = render::DiskColour::Clearance;
            s.scene.layers.boxes = true;
            s.scene.layers.level = 1;
            s.scene.layers.box_colour = render::BoxColour::Tests;
            return s;
        },
        default_ui);
}

/// A crowd record at t = 4 s (the time axis's title used to run over its top tick label), with the Scene
/// and Crowd panels, the latter's plots of fallbacks and contacts included.
TEST(TextOverlap, CrowdRecord) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    check_sizes(
        [&] {
            State s = viewer::load_crowd_state(record, 16.0f / 9.0f);
            viewer::select_choice(s, 0, -1);
            s.scene.cursor = 4.0;
            return s;
        },
        default_ui);
}

}  // namespace
}  // namespace mobb::test
