// The benchmark tables as Markdown, JSON and bar charts (bench/results/).
#pragma once
#include <string>

#include "scale.h"
#include "tables.h"

namespace mobb::bench {

/// Markdown table (the paper's columns plus "x sweep" and positives), the targets, then the notes.
std::string table_markdown(const BenchTable& t);
/// {"workload", "title", "targets": [...], "notes": {...}, "rows": [{"method", "us_per_query", "x_sweep", ...}]}.
std::string table_json(const BenchTable& t);
/// Horizontal bar chart of microseconds per query per method. Throws std::runtime_error when the file
/// cannot be written.
void write_table_png(const BenchTable& t, const std::string& file);

std::string scale_markdown(const ScaleTable& t);
/// {"workload": "scale", "title", "targets", "notes", "rows": [{"method": "crowd N agents",
/// "us_per_query" (CD time per query), "agents", ...}]}.
std::string scale_json(const ScaleTable& t);
/// Bar chart of CD microseconds per agent per simulated second per crowd size.
void write_scale_png(const ScaleTable& t, const std::string& file);

}  // namespace mobb::bench
