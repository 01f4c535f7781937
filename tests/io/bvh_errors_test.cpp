// Malformed BVH: every case throws LoadError "FILE:LINE: message" on one line, with the offending line.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bvh.h"
#include "mobb/io/load.h"
#include "test_util.h"

namespace mobb::io {
namespace {

// A valid file; the comments give the line numbers the tests refer to.
std::vector<std::string> base_lines() {
    return {
        "HIERARCHY",                                                                 // 1
        "ROOT hips",                                                                 // 2
        "{",                                                                         // 3
        "  OFFSET 0 0 0",                                                            // 4
        "  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation",  // 5
        "  JOINT spine",                                                             // 6
        "  {",                                                                       // 7
        "    OFFSET 0 10 0",                                                         // 8
        "    CHANNELS 3 Zrotation Xrotation Yrotation",                              // 9
        "    End Site",                                                              // 10
        "    {",                                                                     // 11
        "      OFFSET 0 5 0",                                                        // 12
        "    }",                                                                     // 13
        "  }",                                                                       // 14
        "}",                                                                         // 15
        "MOTION",                                                                    // 16
        "Frames: 2",                                                                 // 17
        "Frame Time: 0.1",                                                           // 18
        "0 0 0 0 0 0 0 0 0",                                                         // 19
        "1 0 0 0 0 0 0 0 0",                                                         // 20
    };
}

std::string join(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    return text;
}

// The base file with line `line` (1-based) replaced by `text` (which may hold several lines).
std::string with_line(int line, const std::string& text) {
    std::vector<std::string> lines = base_lines();
    lines.at(std::size_t(line - 1)) = text;
    return join(lines);
}

void expect_error(const std::string& text, int line, const std::string& fragment) {
    const std::string message = test::load_error([&] { bvh::parse(text, "bad.bvh"); });
    const std::string prefix = "bad.bvh:" + std::to_string(line) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << "expected prefix '" << prefix << "' in: " << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\r'), std::string::npos) << message;
}

TEST(BvhErrors, BaseFileIsValid) {
    const bvh::Document doc = bvh::parse(join(base_lines()), "ok.bvh");
    EXPECT_EQ(doc.joints.size(), 3u);
    EXPECT_EQ(doc.frames, 2);
    EXPECT_EQ(doc.channels, 9);
}

TEST(BvhErrors, EmptyOrNotBvh) {
    expect_error("", 1, "expected HIERARCHY, found end of file");
    expect_error("\n\n   \n", 4, "expected HIERARCHY");
    expect_error("hello world", 1, "expected HIERARCHY, found 'hello'");
    expect_error(std::string("HIER\0\x01\xff", 7), 1, "expected HIERARCHY");
    expect_error("HIERARCHY\nJOINT a", 2, "expected ROOT");
}

TEST(BvhErrors, MissingOpeningBrace) { expect_error(with_line(7, ""), 8, "expected '{', found 'OFFSET'"); }

TEST(BvhErrors, MissingClosingBrace) { expect_error(with_line(14, ""), 16, "closing 'hips' (line 2), found 'MOTION'"); }

TEST(BvhErrors, ExtraClosingBrace) { expect_error(with_line(15, "}\n}"), 16, "expected MOTION, found '}'"); }

TEST(BvhErrors, TruncatedInsideHierarchy) {
    std::vector<std::string> lines = base_lines();
    lines.resize(12);
    std::string text = join(lines);
    text.resize(text.size() - 3);  // "OFFSET 0 5" without its last number and newline
    expect_error(text, 12, "expected a number for OFFSET, found end of file");
    lines = base_lines();
    lines.resize(13);
    expect_error(join(lines), 14, "closing 'spine' (line 6), found end of file");
}

TEST(BvhErrors, WrongChannelCounts) {
    expect_error(with_line(9, "CHANNELS 3 Zrotation Xrotation"), 9, "CHANNELS 3 lists only 2 channel names");
    expect_error(with_line(9, "CHANNELS 2 Zrotation Xrotation Yrotation"), 9, "found 'Yrotation'");
    expect_error(with_line(9, "CHANNELS 7 Zrotation Xrotation Yrotation"), 9, "out of range 0..6");
    expect_error(with_line(9, "CHANNELS -1"), 9, "out of range");
    expect_error(with_line(9, "CHANNELS 1000000 Zrotation"), 9, "'1000000' is out of range");
    expect_error(with_line(9, "CHANNELS 99999999999999999999999 Zrotation"), 9, "out of range");
    expect_error(with_line(9, "CHANNELS three Zrotation"), 9, "expected an integer");
}

TEST(BvhErrors, UnknownOrRepeatedChannel) {
    expect_error(with_line(9, "CHANNELS 3 Zrotation Wrotation Yrotation"), 9, "unknown channel 'Wrotation'");
    expect_error(with_line(9, "CHANNELS 3 Zrotation Xrotation Zrotation"), 9, "listed twice");
}

TEST(BvhErrors, BadOffsets) {
    expect_error(with_line(8, "OFFSET 0 ten 0"), 8, "expected a number for OFFSET, found 'ten'");
    expect_error(with_line(8, "OFFSET 0 nan 0"), 8, "out of range");
    expect_error(with_line(8, "OFFSET inf 0 0"), 8, "out of range");
    expect_error(with_line(8, "OFFSET 0 0 1e400"), 8, "out of range");
    expect_error(with_line(8, "OFFSET 0 0 2e9"), 8, "out of range");
    expect_error(with_line(8, "OFFSET 0 1.5.2 0"), 8, "expected a number");
    expect_error(with_line(8, "OFFSET 0 10"), 9, "found 'CHANNELS'");
}

TEST(BvhErrors, MissingNamesAndKeywords) {
    expect_error(with_line(6, "  JOINT\n{"), 6, "JOINT needs a name");
    expect_error(with_line(9, ""), 10, "expected CHANNELS, found 'End'");
    expect_error(with_line(10, "    End Sight"), 10, "expected Site");
    expect_error(with_line(10, "    Joint2 x"), 10, "expected JOINT, End Site or '}'");
}

TEST(BvhErrors, NoChannelsOrSecondRoot) {
    std::vector<std::string> lines = base_lines();
    lines[4] = "CHANNELS 0";
    lines[8] = "CHANNELS 0";
    expect_error(join(lines), 16, "the hierarchy has no channels");
    expect_error(with_line(16, "ROOT other\n{\nOFFSET 0 0 0\nCHANNELS 0\n}\nMOTION"), 16, "more than one ROOT");
}

TEST(BvhErrors, BadFrameCount) {
    expect_error(with_line(17, "Frame Time: 0.1"), 17, "expected Frames, found 'Frame'");
    expect_error(with_line(17, "Frames: -3"), 17, "out of range");
    expect_error(with_line(17, "Frames: 0"), 17, "out of range 1..");
    expect_error(with_line(17, "Frames: 999999999999"), 17, "'999999999999' is out of range");
    expect_error(with_line(17, "Frames: 1.5"), 17, "expected an integer");
    expect_error(with_line(17, "Frames: two"), 17, "expected an integer");
}

TEST(BvhErrors, AbsurdFrameCountIsRejectedBeforeAllocating) {
    // 3 joints * 2e9 frames exceeds the position budget: refused at the header.
    expect_error(with_line(17, "Frames: 2000000000"), 17, "too large");
    // Within the budget but not backed by the input: refused when the numbers run out.
    expect_error(with_line(17, "Frames: 40000000"), 21, "file ends after 2 of 40000000 frames");
}

TEST(BvhErrors, BadFrameTime) {
    expect_error(with_line(18, "Frame Time: 0"), 18, "Frame Time must be positive");
    expect_error(with_line(18, "Frame Time: -0.1"), 18, "Frame Time must be positive");
    expect_error(with_line(18, "Frame Time: nan"), 18, "out of range");
    expect_error(with_line(18, "Frame Time: inf"), 18, "out of range");
    expect_error(with_line(18, "Frame Time: 0.1 fast"), 18, "unexpected 'fast' after Frame Time");
    expect_error(with_line(18, "Frame Tme: 0.1"), 18, "expected Time, found 'Tme:'");
}

TEST(BvhErrors, FrameWithTooFewOrTooManyNumbers) {
    expect_error(with_line(20, "1 0 0 0 0 0 0 0"), 20, "frame 1 has 8 numbers, expected 9");
    expect_error(with_line(19, "0 0 0 0 0 0 0 0 0 0"), 19, "frame 0 has more than 9 numbers");
}

TEST(BvhErrors, FewerFramesThanPromised) {
    expect_error(with_line(17, "Frames: 3"), 21, "file ends after 2 of 3 frames");
}

TEST(BvhErrors, GarbageAfterTheLastFrame) {
    expect_error(join(base_lines()) + "garbage\n", 21, "unexpected 'garbage' after the last frame");
    expect_error(join(base_lines()) + "\n\n0 0 0 0 0 0 0 0 0\n", 23, "after the last frame (Frames: 2)");
}

TEST(BvhErrors, NonFiniteOrBadFrameValues) {
    expect_error(with_line(20, "1 nan 0 0 0 0 0 0 0"), 20, "'nan' for a channel is out of range");
    expect_error(with_line(20, "1 0 inf 0 0 0 0 0 0"), 20, "out of range");
    expect_error(with_line(20, "1 0 0 -infinity 0 0 0 0 0"), 20, "out of range");
    expect_error(with_line(20, "1 0 0 0 1e999 0 0 0 0"), 20, "out of range");
    expect_error(with_line(20, "1 0 0 0 0 x 0 0 0"), 20, "expected a number for a channel, found 'x'");
    expect_error(with_line(20, "1 0 0 0 0 0 0 0 0x10"), 20, "expected a number");
}

TEST(BvhErrors, TinyValuesUnderflowToZero) {
    const bvh::Document doc = bvh::parse(with_line(20, "1e-400 0 0 0 0 0 0 0 +2"), "ok.bvh");
    EXPECT_EQ(doc.values[9], 0.0);
    EXPECT_EQ(doc.values[17], 2.0);
}

TEST(BvhErrors, DeepNestingIsBounded) {
    std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 1 Xrotation\n";
    for (int k = 1; k <= 100000; ++k) text += "JOINT j" + std::to_string(k) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n";
    // JOINT k starts on line 6 + 4 (k - 1); the one at depth kMaxDepth is refused.
    expect_error(text, 6 + 4 * (bvh::kMaxDepth - 1), "nested deeper than");
}

TEST(BvhErrors, TooManyJointsIsBounded) {
    std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 1 Xrotation\n";
    for (int k = 1; k <= bvh::kMaxJoints; ++k) text += "End Site { OFFSET 0 0 0 }\n";
    expect_error(text, 5 + bvh::kMaxJoints, "more than 100000 joints");
}

TEST(BvhErrors, LoadClipNamesTheFileAndLine) {
    const test::TempDir dir;
    const std::string file = dir.write("broken.bvh", with_line(9, "CHANNELS 3 Zrotation Wrotation Yrotation"));
    const std::string message = test::load_error([&] { load_clip(file); });
    EXPECT_EQ(message.rfind(file + ":9: unknown channel 'Wrotation'", 0), 0u) << message;
}

}  // namespace
}  // namespace mobb::io
