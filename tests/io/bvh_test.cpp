// BVH parsing and forward kinematics on small hand-written files with hand-checked results.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bvh.h"
#include "mobb/io/animation.h"
#include "mobb/io/load.h"

namespace mobb::io {
namespace {

constexpr double kTol = 1e-9;

#define EXPECT_VEC(actual, X, Y, Z)              \
    do {                                         \
        const glm::dvec3 a_ = (actual);          \
        EXPECT_NEAR(a_.x, (X), kTol) << #actual; \
        EXPECT_NEAR(a_.y, (Y), kTol) << #actual; \
        EXPECT_NEAR(a_.z, (Z), kTol) << #actual; \
    } while (0)

Animation fk(const std::string& text) { return bvh::animate(bvh::parse(text, "test.bvh"), 1.0); }

// One root with the given channels and a child at `child_offset` with no channels.
std::string two_joints(const std::string& root_channels, const std::string& child_offset, const std::string& frame,
                       const std::string& frame_time = "0.5") {
    const int n = int(std::count(root_channels.begin(), root_channels.end(), ' ')) + 1;
    return "HIERARCHY\nROOT hips\n{\n  OFFSET 0 0 0\n  CHANNELS " + std::to_string(n) + " " + root_channels +
           "\n  End Site\n  {\n    OFFSET " + child_offset + "\n  }\n}\nMOTION\nFrames: 1\nFrame Time: " + frame_time +
           "\n" + frame + "\n";
}

TEST(Bvh, TranslationAndNinetyDegreeRotation) {
    const Animation a =
        fk(two_joints("Xposition Yposition Zposition Zrotation Yrotation Xrotation", "10 0 0", "1 2 3 90 0 0"));
    ASSERT_EQ(a.frames(), 1);
    ASSERT_EQ(a.skeleton.size(), 2);
    EXPECT_VEC(a.at(0, 0), 1, 2, 3);
    EXPECT_VEC(a.at(0, 1), 1, 12, 3);  // (10, 0, 0) turned 90 degrees about Z
    EXPECT_DOUBLE_EQ(a.dt, 0.5);
}

TEST(Bvh, RotationChannelsApplyInListedOrder) {
    // R = Rx(90) Rz(90): Rz takes (1,0,0) to (0,1,0), then Rx takes it to (0,0,1).
    EXPECT_VEC(fk(two_joints("Xrotation Zrotation", "1 0 0", "90 90")).at(0, 1), 0, 0, 1);
    // R = Rz(90) Rx(90): Rx leaves (1,0,0) alone, Rz takes it to (0,1,0).
    EXPECT_VEC(fk(two_joints("Zrotation Xrotation", "1 0 0", "90 90")).at(0, 1), 0, 1, 0);
    // Y: (0,0,1) turned 90 degrees about Y is (1,0,0).
    EXPECT_VEC(fk(two_joints("Yrotation", "0 0 1", "90")).at(0, 1), 1, 0, 0);
}

TEST(Bvh, CmuStyleRootRotationStandsTheSkeletonUp) {
    // The CMU root is rotated -90 degrees about X, so the hip offset (0, 0, 105) points up (+Y).
    const Animation a =
        fk(two_joints("Xposition Yposition Zposition Zrotation Yrotation Xrotation", "0 0 105", "5 0 7 0 0 -90"));
    EXPECT_VEC(a.at(0, 1), 5, 105, 7);
}

TEST(Bvh, SixChannelJointInUnusualOrderAndChainedRotations) {
    const std::string text =
        "HIERARCHY\n"
        "ROOT a\n{\n OFFSET 1 0 0\n CHANNELS 3 Zrotation Xposition Yrotation\n"
        " JOINT b\n {\n  OFFSET 0 2 0\n  CHANNELS 6 Yrotation Xposition Zrotation Zposition Xrotation Yposition\n"
        "  End Site\n  {\n   OFFSET 3 0 0\n  }\n }\n}\n"
        "MOTION\nFrames: 2\nFrame Time: 0.1\n"
        "0 0 0 0 0 0 0 0 0\n"
        "90 5 0 0 1 90 2 0 3\n";
    const Animation a = fk(text);
    ASSERT_EQ(a.frames(), 2);
    ASSERT_EQ(a.skeleton.size(), 3);
    EXPECT_TRUE(a.skeleton.end_site[2]);
    EXPECT_EQ(a.skeleton.parents[1], 0);
    EXPECT_EQ(a.skeleton.parents[2], 1);
    // Rest: offsets add up.
    EXPECT_VEC(a.at(0, 0), 1, 0, 0);
    EXPECT_VEC(a.at(0, 1), 1, 2, 0);
    EXPECT_VEC(a.at(0, 2), 4, 2, 0);
    // Frame 1: root at (1+5, 0, 0), turned Rz(90). b's translation (0+1, 2+3, 0+2) = (1, 5, 2) in the root's
    // frame is (-5, 1, 2) in the world: b at (1, 1, 2). b turns Rz(90) once more: its end site (3, 0, 0)
    // is (-3, 0, 0) in the world: (-2, 1, 2).
    EXPECT_VEC(a.at(1, 0), 6, 0, 0);
    EXPECT_VEC(a.at(1, 1), 1, 1, 2);
    EXPECT_VEC(a.at(1, 2), -2, 1, 2);
}

TEST(Bvh, WhitespaceVariantsParseTheSame) {
    const std::string plain =
        "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation Zrotation\n"
        "JOINT leg one\n{\nOFFSET 0 -1 0\nCHANNELS 3 Xrotation Yrotation Zrotation\nEnd Site\n{\nOFFSET 0 -1 "
        "0\n}\n}\n}\n"
        "MOTION\nFrames: 2\nFrame Time: 0.033333\n0 1 0 30 0 0 45 0 0\n1 1 1 0 20 0 0 0 10\n";
    std::string tabs_crlf;
    for (const char c : plain) {
        if (c == '\n')
            tabs_crlf += " \t \r\n\r\n";  // trailing blanks, CRLF, blank lines
        else if (c == ' ')
            tabs_crlf += "\t";
        else
            tabs_crlf += c;
    }
    std::string lone_cr = plain;
    std::replace(lone_cr.begin(), lone_cr.end(), '\n', '\r');
    const std::string braces_on_name_line = [&] {
        std::string s = plain;
        for (const std::string name : {"ROOT r\n{", "JOINT leg one\n{"}) {
            const auto at = s.find(name);
            s.replace(at, name.size(), name.substr(0, name.size() - 2) + " {");
        }
        return s;
    }();
    const Animation a = fk(plain);
    EXPECT_EQ(a.skeleton.names[1], "leg one");
    EXPECT_DOUBLE_EQ(a.dt, 1.0 / 30.0);
    for (const std::string& variant : {tabs_crlf, lone_cr, braces_on_name_line}) {
        const Animation b = fk(variant);
        ASSERT_EQ(b.positions.size(), a.positions.size());
        EXPECT_EQ(b.skeleton.names, a.skeleton.names);
        for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(b.positions[i], a.positions[i]) << i;
    }
}

TEST(Bvh, ErrorLinesCountCrlfAndLoneCrLikeLf) {
    const std::string lf = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 1 Wrotation\n";
    for (const std::string eol : {"\r\n", "\r"}) {
        std::string text;
        for (const char c : lf) text += c == '\n' ? eol : std::string(1, c);
        try {
            bvh::parse(text, "x.bvh");
            ADD_FAILURE() << "no error";
        } catch (const LoadError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("x.bvh:5: ", 0), 0u) << e.what();
        }
    }
}

TEST(Bvh, FrameTimeIsSnappedToRoundedRates) {
    const auto dt_of = [](const std::string& time) {
        return bvh::animate(bvh::parse(two_joints("Xrotation", "1 0 0", "0", time), "t.bvh"), 1.0).dt;
    };
    EXPECT_EQ(dt_of("0.016667"), 1.0 / 60.0);
    EXPECT_EQ(dt_of("0.0083333"), 1.0 / 120.0);
    EXPECT_EQ(dt_of("0.04"), 1.0 / 25.0);
    EXPECT_EQ(dt_of("0.016683"), 0.016683);  // 59.94 Hz stays as written
    EXPECT_EQ(dt_of("2.5"), 2.5);
}

TEST(Bvh, ScaleMultipliesPositions) {
    const bvh::Document doc = bvh::parse(two_joints("Xposition Yposition Zposition", "10 0 0", "1 2 3"), "s.bvh");
    const Animation a = bvh::animate(doc, 0.01);
    EXPECT_VEC(a.at(0, 1), 0.11, 0.02, 0.03);
}

TEST(Animation, ToGroundMapsAxes) {
    EXPECT_EQ(to_ground({1, 2, 3}, UpAxis::Y), glm::dvec3(1, -3, 2));
    EXPECT_EQ(to_ground({1, 2, 3}, UpAxis::Z), glm::dvec3(1, 2, 3));
}

TEST(Animation, PathUsesRootGroundPositionAndFarthestJointIncludingEndSites) {
    Animation a;
    a.skeleton.names = {"root", "arm", "hand end"};
    a.skeleton.parents = {-1, 0, 1};
    a.skeleton.end_site = {false, false, true};
    a.dt = 0.25;
    // Y-up: ground (X, -Z); the height Y is ignored for r.
    a.positions = {{1, 1, 1}, {1, 5, 2},   {4, 0, 5},   // frame 0: hand end at ground distance hypot(3, 4) = 5
                   {0, 1, 0}, {0.5, 9, 0}, {0, 0, 0}};  // frame 1: farthest is the arm at 0.5
    const Path p = path_of(a, UpAxis::Y);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_DOUBLE_EQ(p.dt, 0.25);
    EXPECT_DOUBLE_EQ(p.samples[0].x, 1);
    EXPECT_DOUBLE_EQ(p.samples[0].y, -1);
    EXPECT_DOUBLE_EQ(p.samples[0].r, 5);
    EXPECT_DOUBLE_EQ(p.samples[1].r, 0.5);
    // Z-up: ground (X, Y).
    const Path z = path_of(a, UpAxis::Z);
    EXPECT_DOUBLE_EQ(z.samples[0].x, 1);
    EXPECT_DOUBLE_EQ(z.samples[0].y, 1);
    EXPECT_DOUBLE_EQ(z.samples[0].r, 4.0);
    EXPECT_DOUBLE_EQ(z.samples[1].r, std::hypot(0.5, 8.0));
}

TEST(Animation, EnclosingPathCentresEachDiskOnTheBody) {
    Animation a;
    a.skeleton.names = {"root", "arm", "hand end"};
    a.skeleton.parents = {-1, 0, 1};
    a.skeleton.end_site = {false, false, true};
    a.dt = 0.25;
    // Z-up. Frame 0: the root at one end of the body, the hand 4 m away: a disk of 2 m halfway, where the
    // root's disk is 4 m. Frame 1: the root in the middle, as wide as the root's disk.
    a.positions = {{0, 0, 1}, {1, 0, 1},  {4, 0, 1},   //
                   {0, 0, 1}, {-1, 0, 1}, {1, 0, 1}};  //
    const Path root = path_of(a, UpAxis::Z);
    const Path body = path_of(a, UpAxis::Z, PathCentre::Enclosing);
    ASSERT_EQ(body.size(), 2u);
    EXPECT_DOUBLE_EQ(body.dt, 0.25);
    EXPECT_DOUBLE_EQ(root.samples[0].r, 4);
    EXPECT_DOUBLE_EQ(body.samples[0].x, 2);
    EXPECT_DOUBLE_EQ(body.samples[0].y, 0);
    EXPECT_DOUBLE_EQ(body.samples[0].r, 2);
    EXPECT_DOUBLE_EQ(body.samples[1].x, 0);
    EXPECT_DOUBLE_EQ(body.samples[1].r, root.samples[1].r);
}

}  // namespace
}  // namespace mobb::io
