// glTF 2.0 writer of animated skeletons (mobb/io/export.h), through tinygltf, and the buffer views it shares
// with the viewer's scene export (mobb/io/gltf_buffer.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "mobb/io/capsule.h"
#include "mobb/io/export.h"
#include "mobb/io/gltf_buffer.h"

namespace mobb::io {

int append_buffer_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
    auto& buffer = model.buffers[0].data;
    while (buffer.size() % 4) buffer.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer.size();
    v.byteLength = bytes;
    v.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model.bufferViews.push_back(v);
    return int(model.bufferViews.size()) - 1;
}

namespace {

glm::vec3 to_gltf(const glm::vec3& g) { return {g.x, g.z, -g.y}; }

class ModelBuilder {
public:
    ModelBuilder() {
        model_.asset.version = "2.0";
        model_.asset.generator = "mobb export-crowd";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    tinygltf::Model& model() { return model_; }
    void reserve(std::size_t bytes) { model_.buffers[0].data.reserve(bytes); }

    template <class T>
    int accessor(const std::vector<T>& v, int component, int type, int target, bool bounds = false) {
        tinygltf::Accessor a;
        a.bufferView = append_buffer_view(model_, v.data(), v.size() * sizeof(T), target);
        a.componentType = component;
        a.type = type;
        a.count = v.size() * sizeof(T) / (component_size(component) * std::size_t(count(type)));
        if (bounds) bounds_of(v, a, count(type));
        model_.accessors.push_back(std::move(a));
        return int(model_.accessors.size()) - 1;
    }

    int material(const std::string& name, const std::array<float, 3>& c) {
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = {c[0], c[1], c[2], 1.0};
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = 0.8;
        m.doubleSided = true;
        model_.materials.push_back(std::move(m));
        return int(model_.materials.size()) - 1;
    }

    int node(tinygltf::Node n, bool scene_root) {
        model_.nodes.push_back(std::move(n));
        const int id = int(model_.nodes.size()) - 1;
        if (scene_root) model_.scenes[0].nodes.push_back(id);
        return id;
    }

private:
    static std::size_t component_size(int c) { return c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : 4; }
    static int count(int type) {
        return type == TINYGLTF_TYPE_SCALAR ? 1 : type == TINYGLTF_TYPE_VEC3 ? 3 : type == TINYGLTF_TYPE_VEC4 ? 4 : 16;
    }

    template <class T>
    static void bounds_of(const std::vector<T>& v, tinygltf::Accessor& a, int n) {
        const auto* f = reinterpret_cast<const float*>(v.data());
        const std::size_t total = v.size() * sizeof(T) / sizeof(float);
        a.minValues.assign(std::size_t(n), 1e300);
        a.maxValues.assign(std::size_t(n), -1e300);
        for (std::size_t i = 0; i < total; ++i) {
            const std::size_t c = i % std::size_t(n);
            a.minValues[c] = std::min(a.minValues[c], double(f[i]));
            a.maxValues[c] = std::max(a.maxValues[c], double(f[i]));
        }
    }

    tinygltf::Model model_;
};

/// Triangles of skinned capsules (capsule.h), in the rest pose.
struct BodyMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<std::array<std::uint16_t, 4>> joints;
    std::vector<glm::vec4> weights;
    std::vector<std::uint32_t> indices;

    /// A capsule from joint p at a to joint j at b (glTF coordinates), weights moving from p to j along it.
    void capsule(const glm::vec3& a, const glm::vec3& b, int p, int j) {
        CapsuleMesh c;
        add_capsule(c, a, b, capsule_radius(glm::length(b - a)));
        const auto base = std::uint32_t(positions.size());
        positions.insert(positions.end(), c.positions.begin(), c.positions.end());
        normals.insert(normals.end(), c.normals.begin(), c.normals.end());
        for (float s : c.along) {
            // Slots of weight 0 name joint 0, as glTF-Validator asks.
            joints.push_back({std::uint16_t(s < 1 ? p : 0), std::uint16_t(s > 0 ? j : 0), 0, 0});
            weights.emplace_back(1.0f - s, s, 0.0f, 0.0f);
        }
        for (std::uint32_t i : c.indices) indices.push_back(base + i);
    }
};

void add_shape(ModelBuilder& out, const ExportShape& shape) {
    std::vector<glm::vec3> pos, nrm;
    std::vector<std::uint32_t> idx;
    const auto& g = shape.ground;
    const float h = float(std::max(shape.height, 0.0));
    auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
        const std::uint32_t i = std::uint32_t(pos.size());
        pos.insert(pos.end(), {a, b, c, d});
        nrm.insert(nrm.end(), {n, n, n, n});
        idx.insert(idx.end(), {i, i + 1, i + 2, i, i + 2, i + 3});
    };
    if (h > 0) {  // walls of the extruded polygon (double-sided material)
        const std::size_t n = g.size() == 2 ? 1 : g.size();
        for (std::size_t k = 0; k < n; ++k) {
            const auto& p = g[k];
            const auto& q = g[(k + 1) % g.size()];
            const glm::vec3 a{float(p[0]), 0.0f, -float(p[1])}, b{float(q[0]), 0.0f, -float(q[1])};
            glm::vec3 nn = glm::cross(b - a, glm::vec3(0, 1, 0));
            nn = glm::length(nn) > 0 ? glm::normalize(nn) : glm::vec3(1, 0, 0);
            if (glm::length(b - a) > 0) quad(a, b, b + glm::vec3(0, h, 0), a + glm::vec3(0, h, 0), nn);
        }
    } else if (g.size() >= 3) {  // a flat fan (goal disks are convex)
        const std::uint32_t i = std::uint32_t(pos.size());
        for (const auto& p : g) {
            pos.emplace_back(float(p[0]), 0.01f, -float(p[1]));
            nrm.emplace_back(0, 1, 0);
        }
        for (std::uint32_t k = 1; k + 1 < g.size(); ++k) idx.insert(idx.end(), {i, i + k + 1, i + k});
    }
    if (idx.empty()) return;
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = out.material(shape.name, shape.color);
    prim.attributes["POSITION"] =
        out.accessor(pos, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    prim.attributes["NORMAL"] =
        out.accessor(nrm, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.indices = out.accessor(idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Mesh mesh;
    mesh.name = shape.name;
    mesh.primitives.push_back(std::move(prim));
    out.model().meshes.push_back(std::move(mesh));
    tinygltf::Node n;
    n.name = shape.name;
    n.mesh = int(out.model().meshes.size()) - 1;
    out.node(std::move(n), true);
}

/// One skeleton: joint nodes, skin, animation channels, and its body when asked.
void add_skeleton(ModelBuilder& out, const ExportScene& scene, const ExportSkeleton& sk, int times,
                  tinygltf::Animation& anim) {
    const std::size_t joints = scene.rig.names.size();
    const auto& parents = scene.rig.parents;
    auto world = [&](int f, std::size_t j) { return to_gltf(sk.positions[std::size_t(f) * joints + j]); };
    auto local = [&](int f, std::size_t j) {
        return parents[j] < 0 ? world(f, j) : world(f, j) - world(f, std::size_t(parents[j]));
    };
    // An armature node per skeleton (no transform) holds its joints: importers (Blender's) make one
    // armature of each, where joints under the scene root alone would share one.
    tinygltf::Node arma;
    arma.name = sk.name;
    const int arma_id = out.node(std::move(arma), true);
    const int first = int(out.model().nodes.size());
    out.model().nodes[std::size_t(arma_id)].children.push_back(first);
    for (std::size_t j = 0; j < joints; ++j) {
        tinygltf::Node n;
        n.name = sk.name + " " + scene.rig.names[j];
        const glm::vec3 t = local(0, j);
        n.translation = {t.x, t.y, t.z};
        out.node(std::move(n), false);
    }
    for (std::size_t j = 1; j < joints; ++j)
        out.model().nodes[std::size_t(first) + std::size_t(parents[j])].children.push_back(first + int(j));
    // The rest pose is frame 0: inverse bind matrices undo its world translations.
    std::vector<float> ibm;
    for (std::size_t j = 0; j < joints; ++j) {
        const glm::vec3 w = world(0, j);
        ibm.insert(ibm.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -w.x, -w.y, -w.z, 1});
    }
    tinygltf::Skin skin;
    skin.name = sk.name;
    skin.skeleton = first;
    for (std::size_t j = 0; j < joints; ++j) skin.joints.push_back(first + int(j));
    skin.inverseBindMatrices = out.accessor(ibm, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, 0);
    out.model().skins.push_back(std::move(skin));
    const int skin_id = int(out.model().skins.size()) - 1;
    std::vector<glm::vec3> values(std::size_t(scene.frames));
    for (std::size_t j = 0; j < joints; ++j) {
        for (int f = 0; f < scene.frames; ++f) values[std::size_t(f)] = local(f, j);
        tinygltf::AnimationSampler s;
        s.input = times;
        s.output = out.accessor(values, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 0);
        s.interpolation = "LINEAR";
        anim.samplers.push_back(std::move(s));
        tinygltf::AnimationChannel c;
        c.sampler = int(anim.samplers.size()) - 1;
        c.target_node = first + int(j);
        c.target_path = "translation";
        anim.channels.push_back(std::move(c));
    }
    if (!scene.bodies) return;
    BodyMesh body;
    for (std::size_t j = 1; j < joints; ++j)
        body.capsule(world(0, std::size_t(parents[j])), world(0, j), parents[j], int(j));
    if (body.indices.empty()) return;
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = out.material(sk.name + " body", sk.color);
    const int vb = TINYGLTF_TARGET_ARRAY_BUFFER;
    prim.attributes["POSITION"] =
        out.accessor(body.positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vb, true);
    prim.attributes["NORMAL"] = out.accessor(body.normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vb);
    prim.attributes["JOINTS_0"] =
        out.accessor(body.joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, vb);
    prim.attributes["WEIGHTS_0"] = out.accessor(body.weights, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, vb);
    prim.indices = out.accessor(body.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Mesh mesh;
    mesh.name = sk.name + " body";
    mesh.primitives.push_back(std::move(prim));
    out.model().meshes.push_back(std::move(mesh));
    tinygltf::Node n;
    n.name = sk.name + " body";
    n.mesh = int(out.model().meshes.size()) - 1;
    n.skin = skin_id;
    out.node(std::move(n), true);
}

bool ends_with(const std::string& s, const std::string& tail) {
    if (s.size() < tail.size()) return false;
    return std::equal(tail.rbegin(), tail.rend(), s.rbegin(), [](char a, char b) { return std::tolower(a) == b; });
}

}  // namespace

std::uintmax_t write_gltf(const ExportScene& scene, const std::string& file) {
    const bool binary = ends_with(file, ".glb");
    if (!binary && !ends_with(file, ".gltf")) throw ExportError(file + ": expected a .glb or .gltf file name");
    const std::size_t joints = scene.rig.names.size();
    if (joints == 0 || scene.rig.parents.size() != joints || scene.frames < 1 || !(scene.dt > 0))
        throw ExportError(file + ": nothing to write (no joints or no frames)");
    for (std::size_t j = 0; j < joints; ++j)
        if ((j == 0) != (scene.rig.parents[j] < 0) || scene.rig.parents[j] >= int(j))
            throw ExportError(file + ": joint " + std::to_string(j) + " has a bad parent");
    for (const ExportSkeleton& sk : scene.skeletons)
        if (sk.positions.size() != joints * std::size_t(scene.frames))
            throw ExportError(file + ": " + sk.name + ": " + std::to_string(sk.positions.size()) +
                              " positions, expected " + std::to_string(joints * std::size_t(scene.frames)));
    ModelBuilder out;
    // The animation dominates: a translation per joint per frame per skeleton (and the times, the bodies).
    out.reserve(scene.skeletons.size() * joints * (std::size_t(scene.frames) * 12 + 64 + (scene.bodies ? 3000 : 0)) +
                std::size_t(scene.frames) * 4 + 4096);
    std::vector<float> t(std::size_t(scene.frames));
    for (int f = 0; f < scene.frames; ++f) t[std::size_t(f)] = float(scene.start + f * scene.dt);
    const int times = out.accessor(t, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, 0, true);
    tinygltf::Animation anim;
    anim.name = "crowd";
    for (const ExportSkeleton& sk : scene.skeletons) add_skeleton(out, scene, sk, times, anim);
    for (const ExportShape& shape : scene.shapes) add_shape(out, shape);
    if (!anim.channels.empty()) out.model().animations.push_back(std::move(anim));
    out.model().buffers[0].uri.clear();

    const std::string tmp = file + ".part";
    tinygltf::TinyGLTF writer;
    const bool ok = writer.WriteGltfSceneToFile(&out.model(), tmp, true, true, !binary, binary);
    std::error_code ec;
    if (!ok) {
        std::filesystem::remove(tmp, ec);
        throw ExportError(
            file + ": cannot write glTF (" +
            (std::filesystem::path(file).has_parent_path() ? "is the folder there and writable?" : "not writable") +
            ")");
    }
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw ExportError(file + ": cannot write glTF (rename failed)");
    }
    return std::filesystem::file_size(file, ec);
}

}  // namespace mobb::io
