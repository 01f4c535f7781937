// Person-readable JSON text: objects indented, arrays of numbers on one line (paths, samples).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mobb::crowd {

/// Like dump(2), except that an array holding no objects or arrays is written on one line, and an
/// array of such arrays puts each on its own line.
std::string readable_json(const nlohmann::ordered_json& j);

/// x rounded to `digits` decimals, so the text stays short (1e-6 m: a micrometre).
double rounded(double x, int digits = 6);

}  // namespace mobb::crowd
