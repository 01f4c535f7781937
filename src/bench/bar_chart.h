// A horizontal bar chart as a PNG (stb_image_write; text by stb_easy_font), for the benchmark tables.
#pragma once
#include <string>
#include <vector>

namespace mobb::bench {

struct Bar {
    std::string label;
    double value = 0;
};

/// Writes the chart; values are drawn to scale from 0, each bar labelled with its value and `unit`.
/// Throws std::runtime_error when the file cannot be written.
void write_bar_chart(const std::string& file, const std::string& title, const std::vector<Bar>& bars,
                     const std::string& unit);

}  // namespace mobb::bench
