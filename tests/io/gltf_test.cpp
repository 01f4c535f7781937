// glTF loading on small hand-written files: samplers, node hierarchy, options and errors.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include "mobb/io/load.h"
#include "test_util.h"

namespace mobb::io {
namespace {

constexpr double kTol = 1e-6;  // float32 storage

struct Accessor {
    const char* type;  // SCALAR, VEC3, VEC4
    std::vector<float> values;
};

// Key times: three keys 2/60 s apart and five keys 1/60 s apart; sampling uses the finer union.
const std::vector<float> kT3 = {0.f, 2.f / 60, 4.f / 60};
const std::vector<float> kT5 = {0.f, 1.f / 60, 2.f / 60, 3.f / 60, 4.f / 60};

float c45() { return float(std::cos(M_PI / 8)); }
float s45() { return float(std::sin(M_PI / 8)); }

// Accessors 0..6 (see the comments); every accessor has its own bufferView.
std::vector<Accessor> accessors() {
    return {
        {"SCALAR", kT3},  // 0: 3 key times
        {"SCALAR", kT5},  // 1: 5 key times
        {"VEC4",
         {0, 0, 0, 1, 0, 0, s45(), c45(), 0, 0, float(M_SQRT1_2), float(M_SQRT1_2)}},  // 2: 0, 45, 90 deg about Z
        {"VEC3", {0, 0, 0, 0, 0, 0.1f, 0, 0, 0.2f, 0, 0, 0.3f, 0, 0, 0.4f}},           // 3: z = 0, 0.1, .. 0.4
        {"VEC3", {0, 0, 0, 0, 0, 0, 0, 60, 0,                                          // 4: cubic: a0 v0 b0
                  0, 0, 0, 2, 0, 0, 0, 0,  0,                                          //           a1 v1 b1
                  0, 0, 0, 2, 0, 0, 0, 0,  0}},                                        //           a2 v2 b2
        {"VEC3", {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0}},                       // 5: constant (1, 0, 0)
        {"VEC4", {0, 0, 0, 1, 0, 0, 0, 1}},                                            // 6: only two rotations
        {"SCALAR", {0.f, 0.f, 1.f}},                                                   // 7: times not increasing
    };
}

// Nodes: 0 Armature at (1,0,0) -> 1 root -> 2 tip at (0,1,0) in the root's frame.
const char* kNodes = R"("nodes": [
  {"name": "Armature", "translation": [1, 0, 0], "children": [1]},
  {"name": "root", "children": [2]},
  {"name": "tip", "translation": [0, 1, 0]}])";

const char* kSkins = R"("skins": [{"joints": [1, 2]}])";

// Animations: "linear" (slerped rotation + translation), "step", "cubic" (with a constant Armature channel
// giving the 1/60 s sampling).
const char* kAnimations = R"("animations": [
  {"name": "linear",
   "channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}},
                {"sampler": 1, "target": {"node": 1, "path": "translation"}}],
   "samplers": [{"input": 0, "output": 2, "interpolation": "LINEAR"},
                {"input": 1, "output": 3}]},
  {"name": "step",
   "channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}},
                {"sampler": 1, "target": {"node": 1, "path": "translation"}}],
   "samplers": [{"input": 0, "output": 2, "interpolation": "STEP"},
                {"input": 1, "output": 3, "interpolation": "LINEAR"}]},
  {"name": "cubic",
   "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}},
                {"sampler": 1, "target": {"node": 0, "path": "translation"}}],
   "samplers": [{"input": 0, "output": 4, "interpolation": "CUBICSPLINE"},
                {"input": 1, "output": 5, "interpolation": "LINEAR"}]}])";

// The whole document; `bin_uri`: "data" for an embedded base64 buffer, a file name for an external one,
// empty for a GLB (buffer 0 is the BIN chunk).
std::string gltf_json(const std::string& nodes, const std::string& skins, const std::string& animations,
                      const std::string& bin_uri, std::size_t* bin_size = nullptr) {
    std::string views, accs, bin;
    const std::vector<Accessor> list = accessors();
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string bytes = test::floats(list[i].values);
        const int width = list[i].type[0] == 'S' ? 1 : list[i].type[3] - '0';
        views += std::string(i ? "," : "") + R"({"buffer": 0, "byteOffset": )" + std::to_string(bin.size()) +
                 R"(, "byteLength": )" + std::to_string(bytes.size()) + "}";
        accs += std::string(i ? "," : "") + R"({"bufferView": )" + std::to_string(i) +
                R"(, "componentType": 5126, "count": )" + std::to_string(list[i].values.size() / std::size_t(width)) +
                R"(, "type": ")" + list[i].type + "\"}";
        bin += bytes;
    }
    if (bin_size) *bin_size = bin.size();
    std::string buffer = R"({"byteLength": )" + std::to_string(bin.size());
    if (bin_uri.empty())
        buffer += "}";
    else if (bin_uri == "data")
        buffer += R"(, "uri": "data:application/octet-stream;base64,)" + test::base64(bin) + "\"}";
    else
        buffer += R"(, "uri": ")" + bin_uri + "\"}";
    std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], )" + nodes;
    if (!skins.empty()) json += ", " + skins;
    if (!animations.empty()) json += ", " + animations;
    json += R"(, "bufferViews": [)" + views + R"(], "accessors": [)" + accs + R"(], "buffers": [)" + buffer + "]}";
    return json;
}

std::string bin_bytes() {
    std::string bin;
    for (const Accessor& a : accessors()) bin += test::floats(a.values);
    return bin;
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

#define EXPECT_VEC(actual, X, Y, Z)              \
    do {                                         \
        const glm::dvec3 a_ = (actual);          \
        EXPECT_NEAR(a_.x, (X), kTol) << #actual; \
        EXPECT_NEAR(a_.y, (Y), kTol) << #actual; \
        EXPECT_NEAR(a_.z, (Z), kTol) << #actual; \
    } while (0)

class Gltf : public ::testing::Test {
protected:
    std::string write_gltf(const std::string& json, const std::string& name = "arm.gltf") {
        return dir_.write(name, json);
    }
    std::string standard() { return gltf_json(kNodes, kSkins, kAnimations, "data"); }
    Clip load(const std::string& animation = "", const std::string& json = "") {
        LoadOptions o;
        o.animation = animation;
        return load_clip(write_gltf(json.empty() ? standard() : json), o);
    }
    // Expects a LoadError starting with "FILE: " + element.
    void expect_error(const std::string& json, const std::string& element, const std::string& fragment,
                      const LoadOptions& o = {}) {
        const std::string file = write_gltf(json, "bad.gltf");
        const std::string message = test::load_error([&] { load_clip(file, o); });
        EXPECT_EQ(message.rfind(file + ": " + element, 0), 0u) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    test::TempDir dir_;
};

TEST_F(Gltf, SkeletonFromTheSkinWithAncestorTransforms) {
    const Clip clip = load();
    const Skeleton& s = clip.animation.skeleton;
    EXPECT_EQ(s.names, (std::vector<std::string>{"root", "tip"}));
    EXPECT_EQ(s.parents, (std::vector<int>{-1, 0}));
    EXPECT_EQ(s.root, 0);
    EXPECT_EQ(clip.scale_reason, "glTF: metres");
    EXPECT_DOUBLE_EQ(clip.path.dt, 1.0 / 60.0);
    ASSERT_EQ(clip.animation.frames(), 5);
    // Sample 0: the Armature's (1,0,0) moves both joints.
    EXPECT_VEC(clip.animation.at(0, 0), 1, 0, 0);
    EXPECT_VEC(clip.animation.at(0, 1), 1, 1, 0);
}

TEST_F(Gltf, LinearSamplersSlerpRotationsAndLerpTranslations) {
    const Clip clip = load("linear");
    // Sample 1 (t = 1/60) is halfway between rotation keys 0 and 45 degrees: 22.5 degrees about Z.
    const double a = M_PI / 8;
    EXPECT_VEC(clip.animation.at(1, 0), 1, 0, 0.1);
    EXPECT_VEC(clip.animation.at(1, 1), 1 - std::sin(a), std::cos(a), 0.1);
    EXPECT_VEC(clip.animation.at(4, 1), 0, 0, 0.4);  // 90 degrees: the tip points along -X
    EXPECT_TRUE(clip.warnings.empty());
    // The path: Y-up, ground (X, -Z); r is the tip's ground distance.
    EXPECT_NEAR(clip.path.samples[1].y, -0.1, kTol);
    EXPECT_NEAR(clip.path.samples[1].r, std::sin(a), kTol);
}

TEST_F(Gltf, StepSamplersHoldThePreviousKey) {
    const Clip clip = load("step");
    EXPECT_VEC(clip.animation.at(1, 1), 1, 1, 0.1);                                        // still key 0
    EXPECT_VEC(clip.animation.at(2, 1), 1 - std::sin(M_PI / 4), std::cos(M_PI / 4), 0.2);  // key 1: 45 degrees
    EXPECT_VEC(clip.animation.at(3, 1), 1 - std::sin(M_PI / 4), std::cos(M_PI / 4), 0.3);
}

TEST_F(Gltf, CubicSplineSamplersUseTangents) {
    const Clip clip = load("cubic");
    // Halfway (u = 0.5) between v0 = 0 with out-tangent b0 = (0, 60, 0) and v1 = (2, 0, 0), span 2/60 s:
    // 0.5 v0 + 0.125 span b0 + 0.5 v1 = (1, 0.25, 0); plus the Armature's (1, 0, 0).
    EXPECT_VEC(clip.animation.at(1, 0), 2, 0.25, 0);
    EXPECT_VEC(clip.animation.at(2, 0), 3, 0, 0);  // on key 1
    EXPECT_VEC(clip.animation.at(3, 0), 3, 0, 0);  // between equal keys with zero tangents
}

TEST_F(Gltf, GlbContainerLoadsLikeJson) {
    const std::string glb =
        dir_.write("arm.glb", test::make_glb(gltf_json(kNodes, kSkins, kAnimations, ""), bin_bytes()));
    const Clip a = load_clip(glb);
    const Clip b = load();
    EXPECT_EQ(a.animation.positions, b.animation.positions);
}

TEST_F(Gltf, ExternalBuffersMustBeReadableRegularFiles) {
    dir_.write("arm.bin", bin_bytes());
    const Clip external = load_clip(write_gltf(gltf_json(kNodes, kSkins, kAnimations, "arm.bin"), "external.gltf"));
    EXPECT_EQ(external.animation.positions, load().animation.positions);
    expect_error(gltf_json(kNodes, kSkins, kAnimations, "missing.bin"), "glTF:", "not a valid file");
    // A FIFO would block a plain read forever: it is refused instead.
    ASSERT_EQ(::mkfifo((dir_.path() / "pipe.bin").c_str(), 0600), 0);
    expect_error(gltf_json(kNodes, kSkins, kAnimations, "pipe.bin"), "glTF:", "not a valid file");
}

TEST_F(Gltf, OptionsApply) {
    const std::string file = write_gltf(standard());
    LoadOptions o;
    o.frame_begin = 1;
    o.frame_end = 4;
    o.fps = 30;
    o.scale = 2.0;
    o.up = UpAxis::Z;
    const Clip clip = load_clip(file, o);
    EXPECT_EQ(clip.source_index, (std::vector<int>{1, 3}));
    EXPECT_EQ(clip.up, UpAxis::Y);
    EXPECT_EQ(clip.scale_reason, "given: 2 m per unit");
    ASSERT_EQ(clip.warnings.size(), 1u);
    EXPECT_NE(clip.warnings[0].find("--up z is ignored"), std::string::npos);
    EXPECT_VEC(clip.animation.at(0, 0), 2, 0, 0.2);
}

TEST_F(Gltf, SkinChoiceJointOrderAndSeveralRoots) {
    // Joints listed child first: the root is the joint without a joint ancestor, wherever it is listed.
    Clip clip = load("", gltf_json(kNodes, R"("skins": [{"joints": [1]}, {"joints": [2, 1]}])", kAnimations, "data"));
    EXPECT_EQ(clip.animation.skeleton.size(), 1);
    LoadOptions o;
    o.skin = 1;
    clip = load_clip(
        write_gltf(gltf_json(kNodes, R"("skins": [{"joints": [1]}, {"joints": [2, 1]}])", kAnimations, "data")), o);
    EXPECT_EQ(clip.animation.skeleton.root, 1);
    EXPECT_EQ(clip.animation.skeleton.parents, (std::vector<int>{1, -1}));
    // Joints 0 and 2 are not related: two trees, a warning, the first is the root.
    const std::string plain_nodes = kNodes;
    const std::string nodes = plain_nodes.substr(0, plain_nodes.size() - 1) + R"(, {"name": "x"}])";
    clip = load("", gltf_json(nodes, R"("skins": [{"joints": [0, 3]}])", kAnimations, "data"));
    EXPECT_EQ(clip.animation.skeleton.root, 0);
    ASSERT_EQ(clip.warnings.size(), 1u);
    EXPECT_NE(clip.warnings[0].find("skins[0]: the joints form 2 separate trees"), std::string::npos);
}

TEST_F(Gltf, MissingPartsAreErrors) {
    expect_error(gltf_json(kNodes, "", kAnimations, "data"), "skins:", "no skin");
    expect_error(gltf_json(kNodes, kSkins, "", "data"), "animations:", "no animation");
    LoadOptions o;
    o.skin = 3;
    expect_error(standard(), "skins[3]:", "no such skin (the file has 1)", o);
    o = {};
    o.animation = "dance";
    expect_error(standard(), "animations:", "no animation named 'dance'", o);
}

TEST_F(Gltf, BadIndicesNameTheElement) {
    expect_error(gltf_json(kNodes, R"("skins": [{"joints": [1, 7]}])", kAnimations, "data"),
                 "skins[0].joints[1]:", "node 7 does not exist");
    expect_error(gltf_json(kNodes, R"("skins": [{"joints": [1, 1]}])", kAnimations, "data"),
                 "skins[0].joints[1]:", "listed twice");
    expect_error(replace(standard(), R"("sampler": 1, "target": {"node": 1, "path": "translation"}}],
   "samplers": [{"input": 0, "output": 2, "interpolation": "LINEAR"})",
                         R"("sampler": 9, "target": {"node": 1, "path": "translation"}}],
   "samplers": [{"input": 0, "output": 2, "interpolation": "LINEAR"})"),
                 "animations[0].channels[1]:", "sampler 9 does not exist");
    expect_error(replace(standard(), R"({"input": 0, "output": 2, "interpolation": "LINEAR"})",
                         R"({"input": 99, "output": 2, "interpolation": "LINEAR"})"),
                 "animations[0].samplers[0].input:", "accessor 99 does not exist");
    expect_error(replace(standard(), R"({"node": 1, "path": "rotation"})", R"({"node": 12, "path": "rotation"})"),
                 "animations[0].channels[0]:", "target node 12 does not exist");
    expect_error(replace(standard(), R"("children": [2]})", R"("children": [5]})"),
                 "nodes[1].children[0]:", "node 5 does not exist");
}

TEST_F(Gltf, BadSamplersNameTheElement) {
    const std::string linear = R"({"input": 0, "output": 2, "interpolation": "LINEAR"})";
    expect_error(replace(standard(), linear, R"({"input": 0, "output": 6, "interpolation": "LINEAR"})"),
                 "animations[0].samplers[0].output", "2 values for 3 key times");
    expect_error(replace(standard(), linear, R"({"input": 0, "output": 3, "interpolation": "LINEAR"})"),
                 "animations[0].samplers[0].output (accessors[3]):", "wrong type");
    expect_error(replace(standard(), linear, R"({"input": 7, "output": 2, "interpolation": "LINEAR"})"),
                 "animations[0].samplers[0].input:", "key times do not increase at key 1");
    expect_error(replace(standard(), linear, R"({"input": 0, "output": 2, "interpolation": "QUADRATIC"})"),
                 "animations[0].samplers[0]:", "unknown interpolation 'QUADRATIC'");
    expect_error(replace(standard(), R"("count": 3, "type": "SCALAR")", R"("count": 300, "type": "SCALAR")"),
                 "animations[0].samplers[0].input (accessors[0]):", "300 elements do not fit");
    expect_error(replace(standard(), R"("componentType": 5126, "count": 3, "type": "SCALAR")",
                         R"("componentType": 5125, "count": 3, "type": "SCALAR")"),
                 "animations[0].samplers[0].input (accessors[0]):", "componentType 5125");
    expect_error(replace(standard(), R"({"buffer": 0, "byteOffset": 0, "byteLength": 12})",
                         R"({"buffer": 0, "byteOffset": 0, "byteLength": 99999})"),
                 "animations[0].samplers[0].input (accessors[0]):", "lies outside its buffer");
    expect_error(replace(standard(), R"("path": "rotation")", R"("path": "colour")"),
                 "animations[0].channels[0]:", "unknown target path 'colour'");
}

TEST_F(Gltf, BadNodesAreErrors) {
    // A cycle 1 -> 2 -> 1 that no scene reaches.
    expect_error(replace(replace(standard(), R"("children": [1]})", R"("children": []})"),
                         R"("translation": [0, 1, 0]})", R"("translation": [0, 1, 0], "children": [1]})"),
                 "nodes[", "is its own ancestor");
    expect_error(replace(standard(), R"("translation": [0, 1, 0]})", R"("translation": [0, 1]})"),
                 "nodes[2].translation:", "expected 3 numbers");
    expect_error(replace(standard(), R"({"name": "root", "children": [2]})",
                         R"({"name": "root", "children": [2], "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})"),
                 "animations[0].channels[0]:", "which has a matrix");
}

TEST_F(Gltf, CorruptFilesAreErrors) {
    const std::string garbage = dir_.write("garbage.glb", "\x01\x02\x03 not json at all \xff");
    EXPECT_EQ(test::load_error([&] { load_clip(garbage); }).rfind(garbage + ": glTF: not a valid file", 0), 0u);
    const char bad_length[] = "glTF\x02\0\0\0\xff\xff\xff\xff\x10\0\0\0JSON{}";
    const std::string header = dir_.write("header.glb", std::string(bad_length, sizeof bad_length - 1));
    EXPECT_EQ(test::load_error([&] { load_clip(header); }).rfind(header + ": GLB: not a valid file", 0), 0u);
    const std::string empty = dir_.write("empty.gltf", "");
    EXPECT_EQ(test::load_error([&] { load_clip(empty); }).rfind(empty + ": glTF: not a valid file", 0), 0u);
    const std::string json = dir_.write("array.gltf", "[1, 2, 3]");
    EXPECT_EQ(test::load_error([&] { load_clip(json); }).rfind(json + ": ", 0), 0u);
    std::size_t bin_size = 0;
    const std::string full = gltf_json(kNodes, kSkins, kAnimations, "", &bin_size);
    const std::string short_bin = dir_.write("short.glb", test::make_glb(full, bin_bytes().substr(0, 40)));
    EXPECT_EQ(test::load_error([&] { load_clip(short_bin); }).rfind(short_bin + ": GLB: not a valid file", 0), 0u);
    const std::string glb = test::make_glb(full, bin_bytes());
    const std::string truncated = dir_.write("truncated.glb", glb.substr(0, glb.size() / 2));
    EXPECT_EQ(test::load_error([&] { load_clip(truncated); }).rfind(truncated + ": GLB: not a valid file", 0), 0u);
    // The header's length one byte short of the file: the BIN chunk runs past it (tinygltf read past the
    // end of such a file before the chunks were checked).
    std::string past = glb;
    const auto declared = std::uint32_t(past.size() - 1);
    for (int k = 0; k < 4; ++k) past[std::size_t(8 + k)] = char((declared >> (8 * k)) & 0xff);
    const std::string overrun = dir_.write("overrun.glb", past);
    EXPECT_EQ(
        test::load_error([&] { load_clip(overrun); }).rfind(overrun + ": GLB: not a valid file: chunk at byte ", 0),
        0u);
}

TEST_F(Gltf, GlbWithoutSkinOrAnimation) {
    const std::string no_skin =
        dir_.write("noskin.glb", test::make_glb(gltf_json(kNodes, "", kAnimations, ""), bin_bytes()));
    EXPECT_EQ(test::load_error([&] { load_clip(no_skin); }), no_skin + ": skins: the file has no skin");
    const std::string no_anim =
        dir_.write("noanim.glb", test::make_glb(gltf_json(kNodes, kSkins, "", ""), bin_bytes()));
    EXPECT_EQ(test::load_error([&] { load_clip(no_anim); }), no_anim + ": animations: the file has no animation");
}

}  // namespace
}  // namespace mobb::io
