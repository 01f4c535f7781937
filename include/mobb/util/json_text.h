// Person-readable text: JSON with objects indented and arrays of numbers on one line (paths,
// samples), and numbers for tables.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mobb::util {

/// Like dump(2), except that an array holding no objects or arrays is written on one line, and an
/// array of such arrays puts each on its own line.
std::string readable_json(const nlohmann::ordered_json& j);

/// x rounded to `digits` decimals, so the text stays short (1e-6 m: a micrometre).
double rounded(double x, int digits = 6);

/// x in fixed notation with `digits` decimals (the benchmark tables' cells).
std::string fixed(double x, int digits);

}  // namespace mobb::util
