#include "mobb/io/assimp_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "assimp_keys.h"
#include "common.h"
#include "fbx_scan.h"

namespace mobb::io::assimp {
namespace {

constexpr std::size_t kMaxNodes = 1u << 20;

// Nodes flattened depth first (parents before children), so posing is one pass.
struct Node {
    const aiNode* node = nullptr;
    int parent = -1;
    int end = 0;  // one past the last node of its subtree
};

glm::dmat4 to_glm(const aiMatrix4x4& m) {
    glm::dmat4 out(1.0);  // Assimp is row-major, glm column-major
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[c][r] = double(m[r][c]);
    return out;
}

std::string first_line(const char* text) {
    const std::string s = text ? text : "";
    return detail::quote(s.substr(0, s.find('\n')), 200);
}

// A number stored in metadata under `key`, whatever its numeric type.
std::optional<double> number(const aiMetadata* meta, const char* key) {
    if (!meta) return std::nullopt;
    for (unsigned i = 0; i < meta->mNumProperties; ++i) {
        if (std::string(meta->mKeys[i].C_Str()) != key || !meta->mValues[i].mData) continue;
        const void* d = meta->mValues[i].mData;
        switch (meta->mValues[i].mType) {
            case AI_INT32: return double(*static_cast<const std::int32_t*>(d));
            case AI_UINT64: return double(*static_cast<const std::uint64_t*>(d));
            case AI_FLOAT: return double(*static_cast<const float*>(d));
            case AI_DOUBLE: return *static_cast<const double*>(d);
            default: return std::nullopt;
        }
    }
    return std::nullopt;
}

// FBX marks group and armature objects as nulls: they are not joints even when animated.
bool fbx_null(const aiNode* node) {
    const aiMetadata* meta = node->mMetaData;
    if (!meta) return false;
    for (unsigned i = 0; i < meta->mNumProperties; ++i)
        if (std::string(meta->mKeys[i].C_Str()) == "IsNull" && meta->mValues[i].mType == AI_BOOL &&
            meta->mValues[i].mData)
            return *static_cast<const bool*>(meta->mValues[i].mData);
    return false;
}

std::string unit_name(double metres) {
    if (metres == 1) return "metres";
    if (metres == 0.01) return "centimetres";
    if (metres == 0.001) return "millimetres";
    if (std::abs(metres - 0.0254) < 1e-9) return "inches";
    return std::to_string(metres) + " m per unit";
}

class Loader {
public:
    Loader(const std::string& file, const LoadOptions& options) : file_(file), options_(options) {}

    Result run(const std::string& bytes) {
        import(bytes);
        read_settings(bytes);
        flatten();
        choose_animation();
        read_tracks();
        find_skeleton();
        sample();
        return std::move(result_);
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw LoadError(file_ + ": " + message); }
    void warn(const std::string& message) { result_.warnings.push_back(file_ + ": " + message); }

    // What would take Assimp down rather than make it throw (fbx_scan.h).
    void refuse_hazards(const std::string& bytes) const {
        const fbx::Hazards hazards = fbx::hazards(bytes);
        if (hazards.cycle) fail("FBX connections form a cycle through object " + std::to_string(*hazards.cycle));
        if (hazards.impossible_array)
            fail("an FBX array declares more values than the file's " + std::to_string(bytes.size()) +
                 " bytes can hold");
        if (hazards.overrun)
            fail("the FBX record at byte " + std::to_string(*hazards.overrun) +
                 " declares more property bytes than the file holds");
    }

    void import(const std::string& bytes) {
        importer_.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);  // no $AssimpFbx$ helper nodes
        importer_.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);    // no made-up bones (Collada)
        std::string hint = std::filesystem::path(file_).extension().string();
        if (!hint.empty()) hint.erase(0, 1);
        refuse_hazards(bytes);
        const aiScene* scene = nullptr;
        std::string error;
        try {
            scene =
                importer_.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_ValidateDataStructure, hint.c_str());
            if (!scene) error = first_line(importer_.GetErrorString());
        } catch (const std::exception& e) {
            error = first_line(e.what());
        }
        if (!scene) fail("not a readable file: " + (error.empty() ? "unknown error" : error));
        if (!scene->mRootNode) fail("the scene has no nodes");
        scene_ = scene;
    }

    // Assimp fills in FBX's defaults (Y up, centimetres): only settings the file writes count as stated.
    // (FrameRate is set by Assimp's FBX importer alone.)
    void read_settings(const std::string& bytes) {
        const bool fbx = number(scene_->mMetaData, "FrameRate").has_value();
        result_.up = options_.up;
        if (!fbx || fbx::names_property(bytes, "UpAxis")) read_axes();
        if (!fbx || fbx::names_property(bytes, "UnitScaleFactor")) read_unit();
    }

    // The file's up axis. Y and Z up keep their axes (to_ground knows both); X up and negative up axes
    // are turned to Y up.
    void read_axes() {
        const std::optional<double> axis = number(scene_->mMetaData, "UpAxis");
        const std::optional<double> sign = number(scene_->mMetaData, "UpAxisSign");
        if (!axis) {
            result_.up = options_.up;
            return;
        }
        const bool negative = sign && *sign < 0;
        if (!(*axis == 0 || *axis == 1 || *axis == 2)) fail("UpAxis " + std::to_string(*axis) + " is not 0, 1 or 2");
        const int a = int(*axis);
        result_.up = a == 2 && !negative ? UpAxis::Z : UpAxis::Y;
        const glm::dvec3 x(1, 0, 0), z(0, 0, 1);
        if (a == 0) axes_ = glm::rotate(glm::dmat4(1.0), glm::radians(negative ? -90.0 : 90.0), z);
        if (a == 1 && negative) axes_ = glm::rotate(glm::dmat4(1.0), glm::radians(180.0), x);
        if (a == 2 && negative) axes_ = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), x);
        if (options_.up == UpAxis::Z && !(a == 2 && !negative))
            warn("the file states its up axis (UpAxis " + std::to_string(a) + "); --up z is ignored");
    }

    void read_unit() {
        const std::optional<double> cm = number(scene_->mMetaData, "UnitScaleFactor");
        if (!cm) return;
        if (!(*cm > 0) || !std::isfinite(*cm)) fail("UnitScaleFactor " + std::to_string(*cm) + " is not positive");
        result_.unit = *cm * 0.01;
        char text[32];
        std::snprintf(text, sizeof text, "%g", *cm);
        result_.unit_reason = std::string("FBX UnitScaleFactor ") + text + ": " + unit_name(result_.unit);
    }

    void flatten() {
        std::vector<std::pair<const aiNode*, int>> stack{{scene_->mRootNode, -1}};
        while (!stack.empty()) {
            const auto [node, parent] = stack.back();
            stack.pop_back();
            if (nodes_.size() >= kMaxNodes) fail("more than " + std::to_string(kMaxNodes) + " nodes");
            if (parent >= 0) children_[std::size_t(parent)].push_back(int(nodes_.size()));
            nodes_.push_back({node, parent, 0});
            children_.emplace_back();
            const int self = int(nodes_.size()) - 1;
            for (unsigned c = node->mNumChildren; c-- > 0;)
                if (node->mChildren[c]) stack.push_back({node->mChildren[c], self});
        }
        // Pre-order: a subtree is a contiguous range ending where the next sibling of an ancestor starts.
        for (std::size_t i = nodes_.size(); i-- > 0;) {
            nodes_[i].end = int(i) + 1;
            for (const int c : children_[i]) nodes_[i].end = std::max(nodes_[i].end, nodes_[std::size_t(c)].end);
        }
        for (std::size_t i = 0; i < nodes_.size(); ++i) by_name_.emplace(nodes_[i].node->mName.C_Str(), int(i));
    }

    void choose_animation() {
        if (scene_->mNumAnimations == 0 || !scene_->mAnimations) fail("the file has no animation");
        if (options_.animation.empty()) {
            animation_ = scene_->mAnimations[0];
            return;
        }
        std::string names;
        for (unsigned a = 0; a < scene_->mNumAnimations; ++a) {
            const std::string name = scene_->mAnimations[a]->mName.C_Str();
            if (name == options_.animation) {
                animation_ = scene_->mAnimations[a];
                return;
            }
            if (a < 10) names += std::string(names.empty() ? "" : ", ") + "'" + detail::quote(name) + "'";
        }
        fail("no animation named '" + detail::quote(options_.animation) + "' (the file has " + names + ")");
    }

    void read_tracks() {
        const std::string name = animation_->mName.C_Str();
        animation_label_ = "animation '" + detail::quote(name) + "'";
        double tps = animation_->mTicksPerSecond;
        if (!(tps > 0) || !std::isfinite(tps)) {
            warn(animation_label_ + " states no tick rate; key times are taken as seconds");
            tps = 1;
        }
        track_of_.assign(nodes_.size(), -1);
        for (unsigned c = 0; c < animation_->mNumChannels; ++c) {
            const aiNodeAnim* channel = animation_->mChannels[c];
            if (!channel) continue;
            const auto it = by_name_.find(channel->mNodeName.C_Str());
            if (it == by_name_.end() || track_of_[std::size_t(it->second)] >= 0) continue;
            const std::string where =
                file_ + ": " + animation_label_ + ", channel '" + detail::quote(channel->mNodeName.C_Str()) + "'";
            tracks_.push_back(read_track(*channel, tps, where));
            tracks_.back().node = it->second;
            track_of_[std::size_t(it->second)] = int(tracks_.size()) - 1;
        }
    }

    // The first node, depth first, that is a joint; or the node named --root when it lies outside that
    // joint's subtree (another character). Mesh nodes are not joints.
    void find_skeleton() {
        std::vector<bool> bone(nodes_.size(), false);
        for (unsigned m = 0; m < scene_->mNumMeshes; ++m) {
            const aiMesh* mesh = scene_->mMeshes[m];
            for (unsigned b = 0; mesh && b < mesh->mNumBones; ++b) {
                const auto it = by_name_.find(mesh->mBones[b]->mName.C_Str());
                if (it != by_name_.end()) bone[std::size_t(it->second)] = true;
            }
        }
        int top = -1;
        for (std::size_t i = 0; i < nodes_.size() && top < 0; ++i) {
            const aiNode* n = nodes_[i].node;
            const bool moves = track_of_[i] >= 0 && tracks_[std::size_t(track_of_[i])].moves();
            if ((bone[i] || moves) && !fbx_null(n) && n->mNumMeshes == 0) top = int(i);
        }
        if (!options_.root.empty()) {
            const auto it = by_name_.find(options_.root);
            if (it != by_name_.end() && (top < 0 || it->second < top || it->second >= nodes_[std::size_t(top)].end))
                top = it->second;
        }
        if (top < 0)
            fail("no skeleton: no node is a mesh bone or moved by " + animation_label_ + " (FBX nulls do not count)");
        build_skeleton(top);
    }

    void build_skeleton(int top) {
        Skeleton& s = result_.animation.skeleton;
        std::vector<int> joint_of(nodes_.size(), -1);
        for (int i = top; i < nodes_[std::size_t(top)].end; ++i) {
            const Node& n = nodes_[std::size_t(i)];
            if (n.node->mNumMeshes > 0) {  // geometry, not a joint: skip its subtree
                i = n.end - 1;
                continue;
            }
            joint_of[std::size_t(i)] = s.size();
            joints_.push_back(i);
            s.names.push_back(n.node->mName.length ? n.node->mName.C_Str() : "node " + std::to_string(i));
            s.parents.push_back(i == top ? -1 : joint_of[std::size_t(n.parent)]);
            s.end_site.push_back(false);
        }
        s.root = 0;
        for (int v = nodes_[std::size_t(top)].parent; v >= 0; v = nodes_[std::size_t(v)].parent) chain_.push_back(v);
        std::reverse(chain_.begin(), chain_.end());
    }

    // Spacing: the file's frame time (FBX: Assimp's ticks are its frames), unless keys are denser (or the
    // format has no frame rate): then the median key spacing.
    double spacing(const std::vector<double>& keys) const {
        std::vector<double> gaps;
        for (std::size_t k = 1; k < keys.size(); ++k) gaps.push_back(keys[k] - keys[k - 1]);
        double median = 1.0 / 60.0;
        if (!gaps.empty()) {
            std::nth_element(gaps.begin(), gaps.begin() + std::ptrdiff_t(gaps.size() / 2), gaps.end());
            median = gaps[gaps.size() / 2];
        }
        const bool fbx_rate = number(scene_->mMetaData, "FrameRate").has_value();
        const double frame = fbx_rate ? 1.0 / animation_->mTicksPerSecond : 0;
        return frame > 0 && std::isfinite(frame) && frame <= median * (1 + 1e-6) ? frame : median;
    }

    void sample() {
        std::vector<double> keys;
        for (const int v : chain_) append_keys(v, keys);
        for (const int v : joints_) append_keys(v, keys);
        if (keys.empty()) fail(animation_label_ + " moves no joint of the skeleton");
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end(), [](double a, double b) { return b - a < 1e-9; }), keys.end());
        const double step = spacing(keys);
        const double first = keys.front(), last = keys.back();
        const double count = std::round((last - first) / step) + 1;
        const double joints = double(joints_.size());
        if (!(count <= detail::kMaxSamples) || count * joints > double(detail::kMaxPositions))
            fail(animation_label_ + ": too many samples (" + std::to_string(count) + " of " +
                 std::to_string(joints_.size()) + " joints)");
        report_uneven(keys, first, step);
        result_.source_dt = step;
        Animation& anim = result_.animation;
        anim.dt = detail::snap_dt(step);
        const auto n = std::size_t(count);
        anim.positions.resize(n * joints_.size());
        world_.assign(nodes_.size(), glm::dmat4(1.0));
        for (std::size_t i = 0; i < n; ++i)
            pose(std::min(first + double(i) * step, last), anim.positions.data() + i * joints_.size(), i);
    }

    void append_keys(int node, std::vector<double>& keys) const {
        if (track_of_[std::size_t(node)] < 0) return;
        const Track& t = tracks_[std::size_t(track_of_[std::size_t(node)])];
        keys.insert(keys.end(), t.translation.times.begin(), t.translation.times.end());
        keys.insert(keys.end(), t.rotation.times.begin(), t.rotation.times.end());
        keys.insert(keys.end(), t.scale.times.begin(), t.scale.times.end());
    }

    void report_uneven(const std::vector<double>& keys, double first, double step) {
        std::size_t off = 0;
        for (const double k : keys)
            if (std::abs(k - first - std::round((k - first) / step) * step) > 1e-3 * step) ++off;
        if (off == 0) return;
        char text[160];
        std::snprintf(text, sizeof text, ": %zu of %zu key times are off the %.6g s grid; resampled on it (%.4g fps)",
                      off, keys.size(), step, 1.0 / step);
        warn(animation_label_ + text);
    }

    glm::dmat4 local(int node, double time) const {
        const int t = track_of_[std::size_t(node)];
        const aiNode* n = nodes_[std::size_t(node)].node;
        if (t < 0) return to_glm(n->mTransformation);
        return tracks_[std::size_t(t)].at(time, n->mTransformation);
    }

    void pose(double time, glm::dvec3* out, std::size_t sample) {
        glm::dmat4 base(1.0);
        for (const int v : chain_) base = base * local(v, time);
        for (std::size_t k = 0; k < joints_.size(); ++k) {
            const int v = joints_[k];
            const int p = result_.animation.skeleton.parents[k];
            const glm::dmat4& parent = p < 0 ? base : world_[std::size_t(joints_[std::size_t(p)])];
            world_[std::size_t(v)] = parent * local(v, time);
            out[k] = glm::dvec3(axes_ * world_[std::size_t(v)][3]);
            if (!std::isfinite(out[k].x) || !std::isfinite(out[k].y) || !std::isfinite(out[k].z))
                fail(animation_label_ + ": joint '" + detail::quote(result_.animation.skeleton.names[k]) +
                     "' has a non-finite position at sample " + std::to_string(sample));
        }
    }

    const std::string& file_;
    const LoadOptions& options_;
    Assimp::Importer importer_;  // owns the scene
    const aiScene* scene_ = nullptr;
    const aiAnimation* animation_ = nullptr;
    std::string animation_label_;
    glm::dmat4 axes_{1.0};                    // file axes to Y or Z up
    std::vector<Node> nodes_;                 // depth first
    std::vector<std::vector<int>> children_;  // per node
    std::map<std::string, int> by_name_;      // first node of each name
    std::vector<Track> tracks_;
    std::vector<int> track_of_;      // per node: its track, or -1
    std::vector<int> joints_;        // per joint: its node
    std::vector<int> chain_;         // ancestors of the skeleton's top node, outermost first
    std::vector<glm::dmat4> world_;  // per node: world matrix of the sample being posed
    Result result_;
};

}  // namespace

bool reads(const std::string& extension) {
    std::string ext = extension;
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    if (ext.size() < 2 || ext[0] != '.') return false;
    const Assimp::Importer importer;
    return importer.IsExtensionSupported(ext);
}

std::vector<std::string> extensions() {
    std::string list;  // "*.3d;*.3ds;...;*.mesh.xml;..."
    const Assimp::Importer importer;
    importer.GetExtensionList(list);
    std::vector<std::string> out;
    std::size_t begin = 0;
    while (begin < list.size()) {
        std::size_t end = list.find(';', begin);
        if (end == std::string::npos) end = list.size();
        const std::string entry = list.substr(begin, end - begin);
        begin = end + 1;
        const std::size_t dot = entry.rfind('.');
        if (dot == std::string::npos || dot + 1 == entry.size()) continue;
        std::string ext = entry.substr(dot);
        for (char& c : ext)
            if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        out.push_back(ext);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Result load(const std::string& file, const std::string& bytes, const LoadOptions& options) {
    return Loader(file, options).run(bytes);
}

}  // namespace mobb::io::assimp
