// BVH writer of one animated skeleton (mobb/io/export.h): position channels on every joint.
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "mobb/io/export.h"

namespace mobb::io {

namespace {

/// BVH names end at the line's end and readers split them on blanks: blanks become '_'.
std::string bvh_name(std::string name) {
    for (char& c : name)
        if (c == ' ' || c == '\t' || c == '{' || c == '}') c = '_';
    return name.empty() ? "joint" : name;
}

// Micrometres, without trailing zeros: a third of a crowd's channels are exactly zero (rigid joints), and
// "0" instead of "0.000000" made the 100-agent export's text about a third smaller, losing nothing.
void append(std::string& out, double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6);
    const char* end = r.ptr;
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
    if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {  // -0 is 0
        out += '0';
        return;
    }
    out.append(buf, std::size_t(end - buf));
}

}  // namespace

std::uintmax_t write_bvh(const ExportScene& scene, int skeleton, const std::string& file) {
    const std::size_t joints = scene.rig.names.size();
    if (skeleton < 0 || std::size_t(skeleton) >= scene.skeletons.size())
        throw ExportError(file + ": no skeleton " + std::to_string(skeleton));
    const ExportSkeleton& sk = scene.skeletons[std::size_t(skeleton)];
    if (joints == 0 || scene.frames < 1 || !(scene.dt > 0) || sk.positions.size() != joints * std::size_t(scene.frames))
        throw ExportError(file + ": nothing to write (no joints or no frames)");
    // Y up: ground (x, y, h) is (x, h, -y); a joint's channels are its offset from its parent minus the OFFSET.
    auto world = [&](int f, std::size_t j) {
        const glm::vec3& g = sk.positions[std::size_t(f) * joints + j];
        return glm::dvec3(g.x, g.z, -double(g.y));
    };
    auto local = [&](int f, std::size_t j) {
        const int p = scene.rig.parents[j];
        return p < 0 ? world(f, j) : world(f, j) - world(f, std::size_t(p));
    };
    std::vector<std::vector<std::size_t>> children(joints);
    for (std::size_t j = 1; j < joints; ++j) {
        const int p = scene.rig.parents[j];
        if (p < 0 || std::size_t(p) >= j)
            throw ExportError(file + ": joint " + std::to_string(j) + " has a bad parent");
        children[std::size_t(p)].push_back(j);
    }
    std::vector<std::size_t> order;  // joints in the order the hierarchy lists them (depth first)
    std::string text = "HIERARCHY\n";
    auto write = [&](auto&& self, std::size_t j, int depth) -> void {
        const std::string pad(std::size_t(depth) * 2, ' ');
        order.push_back(j);
        text += pad + (j == 0 ? "ROOT " : "JOINT ") + bvh_name(scene.rig.names[j]) + "\n" + pad + "{\n";
        const glm::dvec3 o = j == 0 ? glm::dvec3(0.0) : local(0, j);
        text += pad + "  OFFSET ";
        append(text, o.x), text += ' ', append(text, o.y), text += ' ', append(text, o.z);
        text += "\n" + pad + "  CHANNELS 3 Xposition Yposition Zposition\n";
        for (std::size_t c : children[j]) self(self, c, depth + 1);
        if (children[j].empty())
            text += pad + "  End Site\n" + pad + "  {\n" + pad + "    OFFSET 0 0 0\n" + pad + "  }\n";
        text += pad + "}\n";
    };
    write(write, 0, 0);
    char head[96];
    std::snprintf(head, sizeof head, "MOTION\nFrames: %d\nFrame Time: %.9f\n", scene.frames, scene.dt);
    text += head;
    for (int f = 0; f < scene.frames; ++f) {
        for (std::size_t k = 0; k < order.size(); ++k) {
            const std::size_t j = order[k];
            const glm::dvec3 v = j == 0 ? local(f, j) : local(f, j) - local(0, j);
            if (k) text += ' ';
            append(text, v.x), text += ' ', append(text, v.y), text += ' ', append(text, v.z);
        }
        text += '\n';
    }
    const std::string tmp = file + ".part";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            std::error_code ec;
            std::filesystem::remove(tmp, ec);
            throw ExportError(file + ": cannot write BVH");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw ExportError(file + ": cannot write BVH (rename failed)");
    }
    return std::filesystem::file_size(file, ec);
}

}  // namespace mobb::io
