#include "export_gltf.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <tiny_gltf.h>

#include "box_layer.h"
#include "disk_layer.h"
#include "mobb/io/gltf_buffer.h"
#include "space.h"
#include "trace_layer.h"

namespace mobb::viewer {

namespace {

/// Triangles (or lines) with normals, gathered before they become accessors.
struct MeshData {
    std::vector<glm::vec3> positions, normals;
    std::vector<std::uint32_t> indices;

    void vertex(const glm::vec3& p, const glm::vec3& n) {
        indices.push_back(std::uint32_t(positions.size()));
        positions.push_back(p);
        normals.push_back(n);
    }
};

class Builder {
public:
    Builder() {
        model_.asset.version = "2.0";
        model_.asset.generator = "mobb export-gltf";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    int material(const std::string& name, const glm::vec3& color, float alpha) {
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = {color.r, color.g, color.b, alpha};
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = 0.8;
        m.doubleSided = true;
        if (alpha < 1.0f) m.alphaMode = "BLEND";
        model_.materials.push_back(m);
        return int(model_.materials.size()) - 1;
    }

    tinygltf::Primitive primitive(const MeshData& data, int material, int mode) {
        tinygltf::Primitive p;
        p.mode = mode;
        p.material = material;
        p.attributes["POSITION"] = accessor(data.positions, true);
        p.attributes["NORMAL"] = accessor(data.normals, false);
        p.indices = index_accessor(data.indices);
        return p;
    }

    void mesh(const std::string& name, std::vector<tinygltf::Primitive> primitives) {
        if (primitives.empty()) return;
        tinygltf::Mesh m;
        m.name = name;
        m.primitives = std::move(primitives);
        model_.meshes.push_back(std::move(m));
        tinygltf::Node n;
        n.name = name;
        n.mesh = int(model_.meshes.size()) - 1;
        model_.nodes.push_back(n);
        model_.scenes[0].nodes.push_back(int(model_.nodes.size()) - 1);
    }

    tinygltf::Model& model() { return model_; }

private:
    int accessor(const std::vector<glm::vec3>& v, bool bounds) {
        tinygltf::Accessor a;
        a.bufferView =
            io::append_buffer_view(model_, v.data(), v.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.type = TINYGLTF_TYPE_VEC3;
        a.count = v.size();
        if (bounds) {
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (const glm::vec3& p : v) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            a.minValues = {lo.x, lo.y, lo.z};
            a.maxValues = {hi.x, hi.y, hi.z};
        }
        model_.accessors.push_back(a);
        return int(model_.accessors.size()) - 1;
    }

    int index_accessor(const std::vector<std::uint32_t>& v) {
        tinygltf::Accessor a;
        a.bufferView = io::append_buffer_view(model_, v.data(), v.size() * sizeof(std::uint32_t),
                                              TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        a.type = TINYGLTF_TYPE_SCALAR;
        a.count = v.size();
        model_.accessors.push_back(a);
        return int(model_.accessors.size()) - 1;
    }

    tinygltf::Model model_;
};

constexpr int kSegments = 12;

void add_cylinder(MeshData& m, const glm::vec4& disk, double dt, double ts) {
    const float r = disk.w, y0 = float(double(disk.z) * ts), h = float(dt * ts);
    const glm::vec3 c(disk.x, y0, -disk.y);
    for (int k = 0; k < kSegments; ++k) {
        const float a0 = 6.2831853f * float(k) / kSegments, a1 = 6.2831853f * float(k + 1) / kSegments;
        const glm::vec3 n0(std::cos(a0), 0, -std::sin(a0)), n1(std::cos(a1), 0, -std::sin(a1)), up(0, 1, 0);
        const glm::vec3 p0 = c + r * n0, p1 = c + r * n1, q0 = p0 + h * up, q1 = p1 + h * up;
        m.vertex(p0, n0), m.vertex(p1, n1), m.vertex(q1, n1);
        m.vertex(p0, n0), m.vertex(q1, n1), m.vertex(q0, n0);
        m.vertex(c + h * up, up), m.vertex(q0, up), m.vertex(q1, up);
        m.vertex(c, -up), m.vertex(p1, -up), m.vertex(p0, -up);
    }
}

/// One placed box's faces (triangles) and edges (lines).
void add_box(MeshData& faces, MeshData& edges, const Obb3& box, double ts) {
    const auto c = render::corners(box, ts);
    for (const auto& f : render::kBoxFaces) {
        const glm::vec3 &a = c[std::size_t(f[0])], &b = c[std::size_t(f[1])], &d = c[std::size_t(f[2])],
                        &e = c[std::size_t(f[3])];
        glm::vec3 n = glm::cross(b - a, d - a);
        n = glm::length(n) > 0 ? glm::normalize(n) : glm::vec3(0, 1, 0);
        faces.vertex(a, n), faces.vertex(b, n), faces.vertex(d, n);
        faces.vertex(a, n), faces.vertex(d, n), faces.vertex(e, n);
    }
    for (const auto& e : render::kBoxEdges) {
        edges.vertex(c[std::size_t(e[0])], glm::vec3(0, 1, 0));
        edges.vertex(c[std::size_t(e[1])], glm::vec3(0, 1, 0));
    }
}

}  // namespace

GltfSummary export_gltf(const State& s, const std::string& file) {
    const render::Frame frame = frame_of(s);
    const double ts = frame.time_scale;
    Builder out;
    for (std::size_t k = 0; k < frame.clips.size(); ++k) {
        const render::ClipView& clip = frame.clips[k];
        if (!clip.visible) continue;
        const std::string name = s.clips[k].name;
        if (frame.layers.disks) {
            MeshData m;
            for (const glm::vec4& d : render::disk_instances(clip.tree->path(), clip.place))
                add_cylinder(m, d, clip.tree->path().dt, ts);
            const int mat = out.material(name + " disks", clip.color, frame.layers.disks_translucent ? 0.3f : 1.0f);
            out.mesh(name + " disks", {out.primitive(m, mat, TINYGLTF_MODE_TRIANGLES)});
        }
        if (frame.layers.boxes) {
            std::vector<tinygltf::Primitive> prims;
            const int depth = clip.tree->depth();
            for (int level = 0; level < depth; ++level) {
                MeshData faces, edges;
                for (const Node& n : clip.tree->nodes()) {
                    if (n.level != level || (!frame.layers.all_levels &&
                                             !render::shown_at_level(n, frame.layers.level, frame.layers.levels)))
                        continue;
                    add_box(faces, edges, transformed(clip.tree->box3(n), SpaceTimeRigid::of(clip.place)), ts);
                }
                if (faces.positions.empty()) continue;
                const glm::vec3 color = render::level_color(level);
                const std::string lv = " level " + std::to_string(level);
                if (frame.layers.box_faces)
                    prims.push_back(out.primitive(faces, out.material(name + lv + " faces", color, 0.15f),
                                                  TINYGLTF_MODE_TRIANGLES));
                prims.push_back(
                    out.primitive(edges, out.material(name + lv + " edges", color, 1.0f), TINYGLTF_MODE_LINE));
            }
            out.mesh(name + " boxes", std::move(prims));
        }
    }
    if (const TraceEvent* ev = render::current_event(frame)) {
        MeshData faces, edges;
        auto add = [&](const render::ClipView& clip, std::int32_t node) {
            if (node < 0 || node >= std::int32_t(clip.tree->nodes().size())) return;
            add_box(faces, edges,
                    transformed(clip.tree->box3(clip.tree->nodes()[std::size_t(node)]), SpaceTimeRigid::of(clip.place)),
                    ts);
        };
        add(frame.clips[std::size_t(frame.trace.a)], ev->node_a);
        add(frame.clips[std::size_t(frame.trace.b)], ev->node_b);
        const glm::vec3 color = render::outcome_color(ev->outcome);
        out.mesh("trace step " + std::to_string(frame.trace.step),
                 {out.primitive(faces, out.material("trace faces", color, 0.3f), TINYGLTF_MODE_TRIANGLES),
                  out.primitive(edges, out.material("trace edges", color, 1.0f), TINYGLTF_MODE_LINE)});
    }

    tinygltf::TinyGLTF writer;
    const std::string tmp = file + ".part";
    if (!writer.WriteGltfSceneToFile(&out.model(), tmp, true, true, false, true)) {
        std::remove(tmp.c_str());
        throw std::runtime_error(file + ": cannot write glTF");
    }
    if (std::rename(tmp.c_str(), file.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error(file + ": cannot write glTF");
    }
    return {int(out.model().meshes.size()), int(out.model().nodes.size()), int(out.model().materials.size())};
}

}  // namespace mobb::viewer
