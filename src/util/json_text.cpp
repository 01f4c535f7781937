#include "mobb/util/json_text.h"

#include <cmath>
#include <sstream>

namespace mobb::util {

namespace {

bool flat(const nlohmann::ordered_json& j) {
    if (!j.is_array()) return false;
    for (const auto& x : j)
        if (x.is_array() || x.is_object()) return false;
    return true;
}

void write(const nlohmann::ordered_json& j, int indent, std::string& out) {
    const std::string pad(std::size_t(indent), ' '), inner(std::size_t(indent + 2), ' ');
    if (j.is_object() && !j.empty()) {
        out += "{\n";
        std::size_t k = 0;
        for (auto it = j.begin(); it != j.end(); ++it, ++k) {
            out += inner + nlohmann::ordered_json(it.key()).dump() + ": ";
            write(it.value(), indent + 2, out);
            out += k + 1 < j.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (j.is_array() && !j.empty() && !flat(j)) {
        out += "[\n";
        for (std::size_t k = 0; k < j.size(); ++k) {
            out += inner;
            write(j[k], indent + 2, out);
            out += k + 1 < j.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else {
        out += j.dump();
    }
}

}  // namespace

std::string readable_json(const nlohmann::ordered_json& j) {
    std::string out;
    write(j, 0, out);
    out += "\n";
    return out;
}

double rounded(double x, int digits) {
    const double scale = std::pow(10.0, digits);
    const double r = std::round(x * scale) / scale;
    return r == 0 ? 0.0 : r;  // no "-0.0"
}

std::string fixed(double x, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << x;
    return s.str();
}

}  // namespace mobb::util
