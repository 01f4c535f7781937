// The label layout's rule alone, on plain boxes: what wins when two labels meet, what the viewport's
// edge does to a title and to a tick label, and the colour bars' reserved room.
#include <vector>

#include <gtest/gtest.h>

#include "label_layout.h"

namespace mobb::test {
namespace {

using render::LabelRole;
using render::LabelSpot;
using render::TextBox;

constexpr float kGap = 2.0f;

TEST(LabelLayout, TickUnderATitleIsLeftOutAndTheTitleKept) {
    // The time axis's title over its top tick label, as crowds drew them at 900 x 600 ("per s" over "8 s").
    std::vector<LabelSpot> l = {{{60, 180, 120, 190}, LabelRole::Tick}, {{10, 176, 186, 194}, LabelRole::Title}};
    const std::vector<bool> drawn = render::lay_out_labels(l, {}, 900, 600, kGap);
    // The title is placed first, where it was asked for; the tick that would overlap it is left out.
    EXPECT_FALSE(drawn[0]);
    ASSERT_TRUE(drawn[1]);
    EXPECT_EQ(l[1].box.y0, 176.0f);
}

TEST(LabelLayout, TicksCloserThanTheGapKeepTheFirst) {
    std::vector<LabelSpot> l = {{{10, 10, 50, 24}}, {{51, 10, 90, 24}}, {{60, 40, 90, 54}}};
    const std::vector<bool> drawn = render::lay_out_labels(l, {}, 200, 100, kGap);
    EXPECT_EQ(drawn, (std::vector<bool>{true, false, true}));
}

TEST(LabelLayout, TheEdgeMovesATitleInAndLeavesATickOut) {
    std::vector<LabelSpot> l = {{{-30, 50, 60, 64}, LabelRole::Title},
                                {{-5, 80, 30, 94}, LabelRole::Tick},
                                {{180, 80, 210, 94}, LabelRole::Tick}};
    const std::vector<bool> drawn = render::lay_out_labels(l, {}, 200, 100, kGap);
    ASSERT_TRUE(drawn[0]);
    EXPECT_EQ(l[0].box.x0, 2 * kGap);  // moved right until whole and off the edge, its width kept
    EXPECT_EQ(l[0].box.x1, 2 * kGap + 90);
    EXPECT_FALSE(drawn[1]);
    EXPECT_FALSE(drawn[2]);
}

TEST(LabelLayout, ATitleOfAPointOutsideTheViewIsLeftOut) {
    std::vector<LabelSpot> l = {{{-30, 50, 60, 64}, LabelRole::Title, false}};
    EXPECT_FALSE(render::lay_out_labels(l, {}, 200, 100, kGap)[0]);
}

TEST(LabelLayout, ATitleMovesALineOffAnOverlayAndTicksKeepOffTheBars) {
    const std::vector<TextBox> bar = {{170, 20, 190, 90}};
    std::vector<LabelSpot> l = {{{100, 40, 160, 54}, LabelRole::Tick},
                                {{100, 40, 160, 54}, LabelRole::Title},
                                {{120, 40, 165, 54}, LabelRole::Overlay},
                                {{150, 60, 180, 74}, LabelRole::Tick}};
    const std::vector<bool> drawn = render::lay_out_labels(l, bar, 200, 100, kGap);
    EXPECT_FALSE(drawn[0]);
    ASSERT_TRUE(drawn[1]);
    EXPECT_TRUE(drawn[2]);
    EXPECT_FALSE(drawn[3]);  // over the bar
    // One line (14 px and the gap) down, the first free place tried.
    EXPECT_EQ(l[1].box.y0, 40.0f + 16.0f);
    EXPECT_FALSE(l[1].box.near(l[2].box, kGap));
}

/// A time tick cut by the viewport's left edge goes across its axis; one with no free side is left out.
TEST(LabelLayout, ATickWithoutRoomGoesToItsOtherSide) {
    std::vector<LabelSpot> l = {{{-20, 40, 10, 54}}, {{30, 40, 60, 54}}, {{-20, 70, 10, 84}}};
    l[0].other_side = TextBox{20, 40, 50, 54};  // right of the axis, where the second label already stands
    l[1].other_side = TextBox{-20, 40, 10, 54};
    l[2].other_side = TextBox{20, 70, 50, 84};
    const std::vector<bool> drawn = render::lay_out_labels(l, {}, 200, 100, kGap);
    EXPECT_FALSE(drawn[0]);
    EXPECT_TRUE(drawn[1]);
    EXPECT_EQ(l[1].box.x0, 30.0f);  // its own side was free
    ASSERT_TRUE(drawn[2]);
    EXPECT_EQ(l[2].box.x0, 20.0f);
}

}  // namespace
}  // namespace mobb::test
