#include "gltf.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

// The Debian library is built with its defaults (stb_image, filesystem callbacks, nlohmann::json),
// so no TINYGLTF_* macro is defined here: the declarations must match the compiled library, and
// TINYGLTF_IMPLEMENTATION must not be defined because libtinygltf.so already holds the code.
#include <tiny_gltf.h>

#include "common.h"
#include "mobb/io/load.h"

namespace mobb::io::gltf {
namespace {

enum class Target { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, Cubic };

// One animation channel, read and validated: key times and values (3 values per key for CUBICSPLINE:
// in-tangent, value, out-tangent).
struct Track {
    int node = -1;
    Target target = Target::Translation;
    Interpolation interpolation = Interpolation::Linear;
    int width = 3;  // components per value: 3 or 4 (rotation quaternion x, y, z, w)
    std::vector<double> times;
    std::vector<double> values;
};

struct Trs {
    glm::dvec3 t{0.0};
    glm::dquat r{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 s{1.0};
};

std::string at(const std::string& array, std::size_t index) { return array + "[" + std::to_string(index) + "]"; }

// Image data is never needed; skipping it also keeps untrusted bytes away from the image decoder.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// Filesystem access for external buffers of a .gltf: regular files only (no FIFOs or devices that could
// block or never end), at most 2 GiB, and never any writing.
bool regular_file(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

std::string same_path(const std::string& path, void*) { return path; }

bool read_regular_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!regular_file(path, nullptr) || ec || size > (std::uintmax_t(1) << 31)) {
        if (err) *err += "cannot read external file '" + path + "'\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(std::size_t(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        if (err) *err += "cannot read external file '" + path + "'\n";
        return false;
    }
    return true;
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is disabled\n";
    return false;
}

std::string first_line(const std::string& text) {
    const std::string line = text.substr(0, text.find('\n'));
    return detail::quote(line, 200);
}

glm::dmat4 compose(const Trs& p) {
    const glm::dmat3 r = glm::mat3_cast(p.r);
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) m[c] = glm::dvec4(r[c] * p.s[c], 0.0);
    m[3] = glm::dvec4(p.t, 1.0);
    return m;
}

class Loader {
public:
    Loader(const std::string& file, int skin, const std::string& animation)
        : file_(file), skin_index_(skin), animation_name_(animation) {}

    Result run(const std::string& bytes) {
        parse(bytes);
        link_nodes();
        read_skin();
        read_animation();
        sample();
        return std::move(result_);
    }

private:
    [[noreturn]] void fail(const std::string& element, const std::string& message) const {
        throw LoadError(file_ + ": " + element + ": " + message);
    }

    void warn(const std::string& element, const std::string& message) {
        result_.warnings.push_back(file_ + ": " + element + ": " + message);
    }

    void parse(const std::string& bytes) {
        if (bytes.size() >= UINT_MAX) fail("file", "too large for glTF");
        tinygltf::TinyGLTF reader;
        reader.SetImageLoader(&skip_image, nullptr);
        reader.SetFsCallbacks({&regular_file, &same_path, &read_regular_file, &refuse_write, nullptr});
        const std::string base = std::filesystem::path(file_).parent_path().string();
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        const auto size = static_cast<unsigned int>(bytes.size());
        const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
        if (binary) check_chunks(bytes);
        std::string err;
        std::string warn;
        bool ok = false;
        try {
            ok = binary ? reader.LoadBinaryFromMemory(&model_, &err, &warn, data, size, base)
                        : reader.LoadASCIIFromString(&model_, &err, &warn, bytes.data(), size, base);
        } catch (const std::exception& e) {
            err = e.what();
        }
        if (!ok)
            fail(binary ? "GLB" : "glTF", "not a valid file: " + (err.empty() ? "unknown error" : first_line(err)));
    }

    // The GLB container (glTF 2.0 spec, section 4.4): a 12-byte header whose length fits the file, then
    // chunks of an 8-byte header and their data, each inside that length. Checked here because Debian's
    // tinygltf copies a binary chunk that runs past the end (found by fuzz/gltf_fuzz).
    void check_chunks(const std::string& bytes) const {
        const auto u32 = [&](std::size_t at) {
            std::uint32_t v = 0;
            for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + std::size_t(k)]);
            return std::size_t(v);
        };
        if (bytes.size() < 12)
            fail("GLB", "not a valid file: header cut short: " + std::to_string(bytes.size()) + " bytes");
        const std::size_t length = u32(8);
        if (length > bytes.size())
            fail("GLB", "not a valid file: header gives " + std::to_string(length) + " bytes, the file has " +
                            std::to_string(bytes.size()));
        for (std::size_t at = 12; at < length;) {
            if (length - at < 8)
                fail("GLB", "not a valid file: chunk header at byte " + std::to_string(at) + " cut short");
            const std::size_t data = u32(at);
            if (data > length - at - 8)
                fail("GLB", "not a valid file: chunk at byte " + std::to_string(at) + " runs past the end (" +
                                std::to_string(data) + " bytes of data, " + std::to_string(length - at - 8) + " left)");
            at += 8 + data;
        }
    }

    // Parents of every node from the children lists; rejects bad indices, shared children and cycles.
    void link_nodes() {
        const std::size_t n = model_.nodes.size();
        parent_.assign(n, -1);
        for (std::size_t i = 0; i < n; ++i) {
            const auto& children = model_.nodes[i].children;
            for (std::size_t k = 0; k < children.size(); ++k) {
                const int c = children[k];
                const auto element = [&] { return at(at("nodes", i) + ".children", k); };
                if (c < 0 || std::size_t(c) >= n) fail(element(), "node " + std::to_string(c) + " does not exist");
                if (parent_[std::size_t(c)] != -1) fail(element(), "node " + std::to_string(c) + " has two parents");
                parent_[std::size_t(c)] = int(i);
            }
        }
        // Depth of every node, memoised so a long chain costs O(n); a cycle never reaches a root.
        depth_.assign(n, -1);
        std::vector<int> chain;
        for (std::size_t i = 0; i < n; ++i) {
            int v = int(i);
            chain.clear();
            while (v >= 0 && depth_[std::size_t(v)] < 0) {
                if (chain.size() > n) fail(at("nodes", i), "is its own ancestor");
                chain.push_back(v);
                v = parent_[std::size_t(v)];
            }
            int d = v < 0 ? -1 : depth_[std::size_t(v)];
            for (auto it = chain.rbegin(); it != chain.rend(); ++it) depth_[std::size_t(*it)] = ++d;
        }
    }

    void read_skin() {
        if (model_.skins.empty()) fail("skins", "the file has no skin");
        if (skin_index_ < 0 || std::size_t(skin_index_) >= model_.skins.size())
            fail("skins[" + std::to_string(skin_index_) + "]",
                 "no such skin (the file has " + std::to_string(model_.skins.size()) + ")");
        const std::string element = at("skins", std::size_t(skin_index_));
        const auto& joints = model_.skins[std::size_t(skin_index_)].joints;
        if (joints.empty()) fail(element + ".joints", "the skin has no joints");
        joint_of_.assign(model_.nodes.size(), -1);
        for (std::size_t k = 0; k < joints.size(); ++k) {
            const int node = joints[k];
            if (node < 0 || std::size_t(node) >= model_.nodes.size())
                fail(at(element + ".joints", k), "node " + std::to_string(node) + " does not exist");
            if (joint_of_[std::size_t(node)] != -1)
                fail(at(element + ".joints", k), "node " + std::to_string(node) + " is listed twice");
            joint_of_[std::size_t(node)] = int(k);
        }
        joint_nodes_ = joints;
        build_skeleton(element);
        collect_posed_nodes();
    }

    // Nearest ancestor of every node that is a joint (-1 if none), parents before children.
    std::vector<int> joint_ancestors() const {
        std::vector<int> order(model_.nodes.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return depth_[std::size_t(a)] < depth_[std::size_t(b)]; });
        std::vector<int> nearest(order.size(), -1);
        for (const int v : order) {
            const int p = parent_[std::size_t(v)];
            if (p >= 0) nearest[std::size_t(v)] = joint_of_[std::size_t(p)] >= 0 ? p : nearest[std::size_t(p)];
        }
        return nearest;
    }

    void build_skeleton(const std::string& element) {
        Skeleton& s = result_.animation.skeleton;
        s.root = -1;
        int roots = 0;
        const std::vector<int> ancestor = joint_ancestors();
        for (std::size_t k = 0; k < joint_nodes_.size(); ++k) {
            const auto node = std::size_t(joint_nodes_[k]);
            const std::string& name = model_.nodes[node].name;
            s.names.push_back(name.empty() ? "node " + std::to_string(node) : name);
            s.end_site.push_back(false);
            const int p = ancestor[node];
            s.parents.push_back(p < 0 ? -1 : joint_of_[std::size_t(p)]);
            if (p < 0 && roots++ == 0) s.root = int(k);
        }
        if (roots > 1)
            warn(element, "the joints form " + std::to_string(roots) + " separate trees; '" +
                              detail::quote(s.names[std::size_t(s.root)]) + "' is taken as the root");
    }

    // Joints and all their ancestors, parents first: exactly the nodes whose transforms matter.
    void collect_posed_nodes() {
        std::vector<bool> posed(model_.nodes.size(), false);
        for (const int j : joint_nodes_)
            for (int v = j; v >= 0 && !posed[std::size_t(v)]; v = parent_[std::size_t(v)]) {
                posed[std::size_t(v)] = true;
                posed_nodes_.push_back(v);
            }
        std::stable_sort(posed_nodes_.begin(), posed_nodes_.end(),
                         [&](int a, int b) { return depth_[std::size_t(a)] < depth_[std::size_t(b)]; });
        rest_.resize(model_.nodes.size());
        matrix_.assign(model_.nodes.size(), glm::dmat4(1.0));
        for (const int v : posed_nodes_) read_rest(v);
    }

    void read_rest(int index) {
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const std::string element = at("nodes", std::size_t(index));
        const auto check = [&](const std::vector<double>& v, std::size_t n, const char* what) {
            if (!v.empty() && v.size() != n) fail(element + "." + what, "expected " + std::to_string(n) + " numbers");
            for (const double x : v)
                if (!std::isfinite(x)) fail(element + "." + what, "not finite");
        };
        check(node.translation, 3, "translation");
        check(node.rotation, 4, "rotation");
        check(node.scale, 3, "scale");
        check(node.matrix, 16, "matrix");
        Trs& p = rest_[std::size_t(index)];
        if (node.translation.size() == 3) p.t = {node.translation[0], node.translation[1], node.translation[2]};
        if (node.rotation.size() == 4) {
            const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            if (!(glm::length(q) > 0)) fail(element + ".rotation", "zero quaternion");
            p.r = glm::normalize(q);
        }
        if (node.scale.size() == 3) p.s = {node.scale[0], node.scale[1], node.scale[2]};
        if (node.matrix.size() == 16)
            for (int i = 0; i < 16; ++i) matrix_[std::size_t(index)][i / 4][i % 4] = node.matrix[std::size_t(i)];
        else
            matrix_[std::size_t(index)] = compose(p);
    }

    std::size_t choose_animation() {
        if (model_.animations.empty()) fail("animations", "the file has no animation");
        if (animation_name_.empty()) return 0;
        for (std::size_t a = 0; a < model_.animations.size(); ++a)
            if (model_.animations[a].name == animation_name_) return a;
        fail("animations", "no animation named '" + detail::quote(animation_name_) + "'");
    }

    void read_animation() {
        const std::size_t a = choose_animation();
        animation_element_ = at("animations", a);
        const tinygltf::Animation& anim = model_.animations[a];
        for (std::size_t c = 0; c < anim.channels.size(); ++c) read_channel(anim, c);
        if (tracks_.empty()) fail(animation_element_, "no channel animates a node");
    }

    void read_channel(const tinygltf::Animation& anim, std::size_t index) {
        const tinygltf::AnimationChannel& channel = anim.channels[index];
        const std::string element = at(animation_element_ + ".channels", index);
        if (channel.target_path == "weights") return;  // morph weights do not move joints
        Track track;
        if (channel.target_path == "translation")
            track.target = Target::Translation;
        else if (channel.target_path == "rotation")
            track.target = Target::Rotation;
        else if (channel.target_path == "scale")
            track.target = Target::Scale;
        else
            fail(element, "unknown target path '" + detail::quote(channel.target_path) + "'");
        if (channel.target_node < 0) return;  // the target is defined by an extension
        if (std::size_t(channel.target_node) >= model_.nodes.size())
            fail(element, "target node " + std::to_string(channel.target_node) + " does not exist");
        if (channel.sampler < 0 || std::size_t(channel.sampler) >= anim.samplers.size())
            fail(element, "sampler " + std::to_string(channel.sampler) + " does not exist");
        if (model_.nodes[std::size_t(channel.target_node)].matrix.size() == 16)
            fail(element, "targets node " + std::to_string(channel.target_node) + ", which has a matrix");
        track.node = channel.target_node;
        track.width = track.target == Target::Rotation ? 4 : 3;
        read_sampler(anim.samplers[std::size_t(channel.sampler)],
                     at(animation_element_ + ".samplers", std::size_t(channel.sampler)), track);
        tracks_.push_back(std::move(track));
    }

    void read_sampler(const tinygltf::AnimationSampler& sampler, const std::string& element, Track& track) {
        if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty())
            track.interpolation = Interpolation::Linear;
        else if (sampler.interpolation == "STEP")
            track.interpolation = Interpolation::Step;
        else if (sampler.interpolation == "CUBICSPLINE")
            track.interpolation = Interpolation::Cubic;
        else
            fail(element, "unknown interpolation '" + detail::quote(sampler.interpolation) + "'");

        track.times = read_accessor(sampler.input, 1, element + ".input");
        if (track.times.empty()) fail(element + ".input", "no key times");
        for (std::size_t k = 1; k < track.times.size(); ++k)
            if (!(track.times[k] > track.times[k - 1]))
                fail(element + ".input", "key times do not increase at key " + std::to_string(k));

        track.values = read_accessor(sampler.output, track.width, element + ".output");
        const std::size_t per_key = track.interpolation == Interpolation::Cubic ? 3 : 1;
        const std::size_t expected = track.times.size() * per_key;
        if (track.values.size() != expected * std::size_t(track.width))
            fail(element + ".output", std::to_string(track.values.size() / std::size_t(track.width)) + " values for " +
                                          std::to_string(track.times.size()) + " key times (expected " +
                                          std::to_string(expected) + ")");
    }

    // Reads accessor `index` of `width` components per element as doubles, checking every index and
    // byte range against the buffers (tinygltf leaves that to the caller).
    std::vector<double> read_accessor(int index, int width, const std::string& element) {
        if (index < 0 || std::size_t(index) >= model_.accessors.size())
            fail(element, "accessor " + std::to_string(index) + " does not exist");
        const tinygltf::Accessor& acc = model_.accessors[std::size_t(index)];
        const std::string where = element + " (accessors[" + std::to_string(index) + "])";
        const int type = width == 1 ? TINYGLTF_TYPE_SCALAR : width == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
        if (acc.type != type)
            fail(where, "wrong type " + std::to_string(acc.type) + " (expected " + std::to_string(type) + ")");
        if (acc.sparse.isSparse) fail(where, "sparse accessors are not supported");
        const std::size_t component = component_size(acc, where);
        if (acc.bufferView < 0 || std::size_t(acc.bufferView) >= model_.bufferViews.size())
            fail(where, "bufferView " + std::to_string(acc.bufferView) + " does not exist");
        const tinygltf::BufferView& view = model_.bufferViews[std::size_t(acc.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size())
            fail(where, "buffer " + std::to_string(view.buffer) + " does not exist");
        const auto& buffer = model_.buffers[std::size_t(view.buffer)].data;
        if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength)
            fail(where, "bufferView " + std::to_string(acc.bufferView) + " lies outside its buffer");
        const std::size_t element_size = component * std::size_t(width);
        const std::size_t stride = view.byteStride ? view.byteStride : element_size;
        if (stride < element_size) fail(where, "byteStride smaller than an element");
        if (acc.count > 0) {
            const bool fits = acc.byteOffset <= view.byteLength && element_size <= view.byteLength - acc.byteOffset &&
                              acc.count - 1 <= (view.byteLength - acc.byteOffset - element_size) / stride;
            if (!fits)
                fail(where, std::to_string(acc.count) + " elements do not fit in bufferView " +
                                std::to_string(acc.bufferView));
        }
        const unsigned char* base = buffer.data() + view.byteOffset + acc.byteOffset;
        std::vector<double> out;
        out.reserve(acc.count * std::size_t(width));
        for (std::size_t i = 0; i < acc.count; ++i)
            for (std::size_t c = 0; c < std::size_t(width); ++c) {
                const double v = component_value(acc.componentType, base + i * stride + c * component);
                if (!std::isfinite(v)) fail(where, "element " + std::to_string(i) + " is not finite");
                out.push_back(v);
            }
        return out;
    }

    // Bytes per component: float, or normalized integers (allowed by the spec for rotations).
    std::size_t component_size(const tinygltf::Accessor& acc, const std::string& where) const {
        switch (acc.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
            case TINYGLTF_COMPONENT_TYPE_BYTE:
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                if (acc.normalized) return 1;
                break;
            case TINYGLTF_COMPONENT_TYPE_SHORT:
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
                if (acc.normalized) return 2;
                break;
            default: break;
        }
        fail(where, "componentType " + std::to_string(acc.componentType) + (acc.normalized ? " (normalized)" : "") +
                        " is not supported");
    }

    // Little-endian component (glTF's byte order; memcpy because buffers need not be aligned).
    static double component_value(int type, const unsigned char* p) {
        switch (type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float f;
                std::memcpy(&f, p, 4);
                return double(f);
            }
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                signed char b;
                std::memcpy(&b, p, 1);
                return std::max(double(b) / 127.0, -1.0);
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return double(*p) / 255.0;
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t s;
                std::memcpy(&s, p, 2);
                return std::max(double(s) / 32767.0, -1.0);
            }
            default: {
                std::uint16_t s;
                std::memcpy(&s, p, 2);
                return double(s) / 65535.0;
            }
        }
    }

    // Uniform sample times from the first to the last key of any channel, spaced by the median key gap.
    void sample() {
        std::vector<double> keys;
        for (const Track& t : tracks_) keys.insert(keys.end(), t.times.begin(), t.times.end());
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end(), [](double a, double b) { return b - a < 1e-6; }), keys.end());
        double dt = 1.0 / 60.0;
        if (keys.size() > 1) {
            std::vector<double> gaps(keys.size() - 1);
            for (std::size_t k = 1; k < keys.size(); ++k) gaps[k - 1] = keys[k] - keys[k - 1];
            std::nth_element(gaps.begin(), gaps.begin() + std::ptrdiff_t(gaps.size() / 2), gaps.end());
            dt = detail::snap_dt(gaps[gaps.size() / 2]);
        }
        const double first = keys.front();
        const double last = keys.back();
        const double count = std::round((last - first) / dt) + 1;
        const double joints = double(joint_nodes_.size());
        if (!(count <= detail::kMaxSamples) || count * joints > double(detail::kMaxPositions))
            fail(animation_element_,
                 "too many samples (" + std::to_string(count) + " at dt " + std::to_string(dt) + " s)");
        Animation& anim = result_.animation;
        anim.dt = dt;
        const auto n = std::size_t(count);
        anim.positions.resize(n * joint_nodes_.size());
        world_.assign(model_.nodes.size(), glm::dmat4(1.0));
        local_ = rest_;
        animated_.assign(model_.nodes.size(), false);
        for (const Track& t : tracks_) animated_[std::size_t(t.node)] = true;
        for (std::size_t i = 0; i < n; ++i)
            pose(std::min(first + double(i) * dt, last), anim.positions.data() + i * joint_nodes_.size(), i);
    }

    // Every track overwrites its whole component at every sample, so local_ (the rest TRS at first)
    // never needs resetting.
    void pose(double time, glm::dvec3* out, std::size_t sample) {
        for (const Track& t : tracks_) {
            Trs& local = local_[std::size_t(t.node)];
            const glm::dvec4 v = evaluate(t, time);
            if (t.target == Target::Translation)
                local.t = glm::dvec3(v);
            else if (t.target == Target::Scale)
                local.s = glm::dvec3(v);
            else
                local.r = glm::dquat(v.w, v.x, v.y, v.z);
        }
        for (const int v : posed_nodes_) {
            const auto node = std::size_t(v);
            const glm::dmat4 m = animated_[node] ? compose(local_[node]) : matrix_[node];
            const int p = parent_[node];
            world_[node] = p < 0 ? m : world_[std::size_t(p)] * m;
        }
        for (std::size_t k = 0; k < joint_nodes_.size(); ++k) {
            out[k] = glm::dvec3(world_[std::size_t(joint_nodes_[k])][3]);
            if (!std::isfinite(out[k].x) || !std::isfinite(out[k].y) || !std::isfinite(out[k].z))
                fail(animation_element_, "joint '" + detail::quote(result_.animation.skeleton.names[k]) +
                                             "' has a non-finite position at sample " + std::to_string(sample));
        }
    }

    static glm::dvec4 key(const Track& t, std::size_t k, std::size_t part) {
        const std::size_t per_key = t.interpolation == Interpolation::Cubic ? 3 : 1;
        const double* v = t.values.data() + (k * per_key + part) * std::size_t(t.width);
        return {v[0], v[1], v[2], t.width == 4 ? v[3] : 0.0};
    }

    static glm::dvec4 normalized(const Track& t, glm::dvec4 v) {
        if (t.target != Target::Rotation) return v;
        const double length = glm::length(v);
        return length > 0 ? v / length : glm::dvec4(0, 0, 0, 1);
    }

    static glm::dvec4 evaluate(const Track& t, double time) {
        const std::size_t value = t.interpolation == Interpolation::Cubic ? 1 : 0;
        const std::size_t last = t.times.size() - 1;
        if (time <= t.times.front()) return normalized(t, key(t, 0, value));
        if (time >= t.times.back()) return normalized(t, key(t, last, value));
        const auto k = std::size_t(std::upper_bound(t.times.begin(), t.times.end(), time) - t.times.begin()) - 1;
        const double span = t.times[k + 1] - t.times[k];
        double u = (time - t.times[k]) / span;
        // Sample times are exact multiples of dt while keys are float32: land on a key when that close.
        if (u < 1e-3) u = 0;
        if (u > 1 - 1e-3) u = 1;
        if (t.interpolation == Interpolation::Step) return normalized(t, key(t, u >= 1 ? k + 1 : k, 0));
        if (t.interpolation == Interpolation::Cubic) {
            const double u2 = u * u, u3 = u2 * u;
            const glm::dvec4 v = (2 * u3 - 3 * u2 + 1) * key(t, k, 1) + (u3 - 2 * u2 + u) * span * key(t, k, 2) +
                                 (-2 * u3 + 3 * u2) * key(t, k + 1, 1) + (u3 - u2) * span * key(t, k + 1, 0);
            return normalized(t, v);
        }
        if (t.target == Target::Rotation) {
            const glm::dvec4 a = normalized(t, key(t, k, 0));
            const glm::dvec4 b = normalized(t, key(t, k + 1, 0));
            const glm::dquat q = glm::slerp(glm::dquat(a.w, a.x, a.y, a.z), glm::dquat(b.w, b.x, b.y, b.z), u);
            return normalized(t, {q.x, q.y, q.z, q.w});
        }
        return key(t, k, 0) * (1 - u) + key(t, k + 1, 0) * u;
    }

    const std::string& file_;
    int skin_index_;
    const std::string& animation_name_;
    tinygltf::Model model_;
    std::vector<int> parent_;         // per node, -1 for scene roots
    std::vector<int> depth_;          // per node
    std::vector<int> joint_of_;       // per node: index in the skin's joints, or -1
    std::vector<int> joint_nodes_;    // per joint: node index
    std::vector<int> posed_nodes_;    // joints and their ancestors, parents first
    std::vector<Trs> rest_;           // per node: TRS as stored
    std::vector<glm::dmat4> matrix_;  // per node: local matrix as stored
    std::vector<glm::dmat4> world_;   // per node: world matrix of the sample being posed
    std::vector<Trs> local_;          // per node: TRS of the sample being posed
    std::vector<bool> animated_;      // per node: targeted by a track
    std::vector<Track> tracks_;
    std::string animation_element_;
    Result result_;
};

}  // namespace

Result load(const std::string& file, const std::string& bytes, int skin, const std::string& animation) {
    return Loader(file, skin, animation).run(bytes);
}

}  // namespace mobb::io::gltf
