// Small ASCII FBX 7.4 files written by the tests: a two-joint skeleton (hips, and a hand `reach` along
// the hips' X), the hips' X translation keyed, with or without an animation, or the same motion on an
// FBX null (no skeleton). Times in FBX ticks: 46186158000 per second.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mobb::test {

struct AsciiFbx {
    int up_axis = 1;                  ///< GlobalSettings UpAxis: 0 X, 1 Y, 2 Z
    bool write_up = true;             ///< false: no UpAxis / UpAxisSign (the hips still stand along up_axis)
    double unit_cm = 100;             ///< UnitScaleFactor: centimetres per unit (0: not written)
    int time_mode = 6;                ///< TimeMode: 6 = 30 fps, 3 = 60 fps
    std::vector<double> key_seconds;  ///< the hips' X keys; empty: no animation at all
    std::vector<double> key_x;
    double hips_height = 1;  ///< rest translation of the hips along the up axis
    double reach = 0.5;      ///< the hand's rest translation along X
    bool null_only = false;  ///< a single FBX null carries the keys: no skeleton
    std::string stack = "walk";
};

inline std::string ascii_fbx(const AsciiFbx& f) {
    const auto num = [](double v) { return std::to_string(v); };
    const auto ticks = [](double s) { return std::to_string(std::int64_t(s * 46186158000.0 + 0.5)); };
    double t[3] = {0, 0, 0};
    t[f.up_axis] = f.hips_height;
    std::string s =
        "; FBX 7.4.0 project file\n"
        "FBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n"
        "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n";
    if (f.write_up)
        s += "\t\tP: \"UpAxis\", \"int\", \"Integer\", \"\"," + std::to_string(f.up_axis) +
             "\n\t\tP: \"UpAxisSign\", \"int\", \"Integer\", \"\",1\n";
    if (f.unit_cm > 0) s += "\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", \"\"," + num(f.unit_cm) + "\n";
    s += "\t\tP: \"TimeMode\", \"enum\", \"\", \"\"," + std::to_string(f.time_mode) + "\n\t}\n}\nObjects:  {\n";
    const std::string kind = f.null_only ? "Null" : "LimbNode";
    s += "\tNodeAttribute: 2001, \"NodeAttribute::\", \"" + kind + "\" {\n\t\tTypeFlags: \"" +
         (f.null_only ? "Null" : "Skeleton") + "\"\n\t}\n";
    s += "\tModel: 1001, \"Model::hips\", \"" + kind +
         "\" {\n\t\tVersion: 232\n\t\tProperties70:  {\n"
         "\t\t\tP: \"Lcl Translation\", \"Lcl Translation\", \"\", \"A\"," +
         num(t[0]) + "," + num(t[1]) + "," + num(t[2]) + "\n\t\t}\n\t}\n";
    if (!f.null_only)
        s += "\tNodeAttribute: 2002, \"NodeAttribute::\", \"LimbNode\" {\n\t\tTypeFlags: \"Skeleton\"\n\t}\n"
             "\tModel: 1002, \"Model::hand\", \"LimbNode\" {\n\t\tVersion: 232\n\t\tProperties70:  {\n"
             "\t\t\tP: \"Lcl Translation\", \"Lcl Translation\", \"\", \"A\"," +
             num(f.reach) + ",0,0\n\t\t}\n\t}\n";
    const bool animated = !f.key_seconds.empty();
    if (animated) {
        std::string times, values;
        for (std::size_t k = 0; k < f.key_seconds.size(); ++k) {
            times += (k ? "," : "") + ticks(f.key_seconds[k]);
            values += (k ? "," : "") + num(f.key_x[k]);
        }
        const std::string n = std::to_string(f.key_seconds.size());
        s += "\tAnimationStack: 3001, \"AnimStack::" + f.stack +
             "\", \"\" {\n\t}\n"
             "\tAnimationLayer: 3002, \"AnimLayer::Base\", \"\" {\n\t}\n"
             "\tAnimationCurveNode: 3003, \"AnimCurveNode::T\", \"\" {\n\t\tProperties70:  {\n"
             "\t\t\tP: \"d|X\", \"Number\", \"\", \"A\",0\n\t\t\tP: \"d|Y\", \"Number\", \"\", \"A\"," +
             num(t[1]) + "\n\t\t\tP: \"d|Z\", \"Number\", \"\", \"A\"," + num(t[2]) +
             "\n\t\t}\n\t}\n"
             "\tAnimationCurve: 3004, \"AnimCurve::\", \"\" {\n\t\tDefault: 0\n\t\tKeyVer: 4009\n"
             "\t\tKeyTime: *" +
             n + " {\n\t\t\ta: " + times + "\n\t\t}\n\t\tKeyValueFloat: *" + n + " {\n\t\t\ta: " + values +
             "\n\t\t}\n\t}\n";
    }
    s += "}\nConnections:  {\n\tC: \"OO\",1001,0\n\tC: \"OO\",2001,1001\n";
    if (!f.null_only) s += "\tC: \"OO\",1002,1001\n\tC: \"OO\",2002,1002\n";
    if (animated)
        s += "\tC: \"OO\",3002,3001\n\tC: \"OO\",3003,3002\n\tC: \"OP\",3003,1001, \"Lcl Translation\"\n"
             "\tC: \"OP\",3004,3003, \"d|X\"\n";
    s += "}\n";
    return s;
}

}  // namespace mobb::test
