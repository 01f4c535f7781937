// Text, JSON and charts of the benchmark tables (report.h).
#include <algorithm>
#include <functional>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bar_chart.h"
#include "mobb/util/json_text.h"
#include "report.h"

namespace mobb::bench {

using util::fixed;
using util::readable_json;
using util::rounded;

namespace {

nlohmann::ordered_json targets_json(const std::vector<Target>& targets) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const Target& g : targets)
        out.push_back({{"target", g.what},
                       {"goal", g.goal},
                       {"measured", g.known ? nlohmann::ordered_json(rounded(g.measured, 3)) : nullptr},
                       {"met", g.met()},
                       {"text", target_text(g)},
                       {"detail", g.detail}});
    return out;
}

nlohmann::ordered_json notes_json(const std::map<std::string, std::string>& notes) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& [k, v] : notes) out[k] = v;
    return out;
}

void targets_markdown(std::ostream& out, const std::vector<Target>& targets) {
    if (targets.empty()) return;
    out << "Targets (issue 5):\n\n";
    for (const Target& g : targets) out << "- " << g.what << ": " << target_text(g) << " (" << g.detail << ")\n";
    out << "\n";
}

// " [e extra, m missed]" when a method disagrees with brute force.
std::string disagreement_split(const MethodRow& r) {
    if (r.extra + r.missed == 0) return "";
    return " [" + std::to_string(r.extra) + " extra, " + std::to_string(r.missed) + " missed]";
}

std::string ratio_cell(const MethodRow& r) { return r.x_sweep > 0 ? fixed(r.x_sweep, 2) : "-"; }

// A one-thread column of a scale row: "-" when the size ran on the parallel threads only.
std::string one_thread_cell(const ScaleRow& r, double v, int decimals) {
    return r.one_thread ? fixed(v, decimals) : "-";
}

std::string megabytes(std::int64_t bytes) { return bytes < 0 ? "-" : fixed(double(bytes) / 1e6, 0); }

std::string threads_label(int n) { return std::to_string(n) + (n == 1 ? " thread" : " threads"); }

// One line of the thread table: a cell per thread count, "-" for those a size did not run (a size
// from ScaleOptions::parallel_only_from runs the last count only).
void thread_line(std::ostream& out, const ScaleTable& t, const ScaleRow& r, const std::string& label,
                 const std::function<std::string(const ThreadRuns&)>& cell) {
    out << "| " << label;
    const std::size_t skip = t.threads.size() - std::min(t.threads.size(), r.by_threads.size());
    for (std::size_t k = 0; k < t.threads.size(); ++k) out << " | " << (k < skip ? "-" : cell(r.by_threads[k - skip]));
    out << " |\n";
}

std::string share_cell(const std::optional<double>& s) { return s ? fixed(100.0 * *s, 1) + " %" : "-"; }

// Issue 46's table: a block of lines per crowd size, a column per thread count.
void thread_table(std::ostream& out, const ScaleTable& t) {
    if (t.rows.empty() || t.threads.empty()) return;
    const std::string first = threads_label(t.threads.front());
    out << "#### Thread counts\n\n| agents x simulated s";
    for (int n : t.threads) out << " | " << threads_label(n);
    out << " |\n|---";
    for (std::size_t k = 0; k < t.threads.size(); ++k) out << "|---:";
    out << "|\n";
    for (const ScaleRow& r : t.rows) {
        const std::string size = std::to_string(r.agents) + " x " + fixed(t.seconds, 0);
        thread_line(out, t, r, size + ": simulation s", [](const ThreadRuns& c) { return fixed(c.sim_seconds, 3); });
        thread_line(out, t, r, "speed-up over " + first,
                    [](const ThreadRuns& c) { return c.speedup > 0 ? fixed(c.speedup, 2) : "-"; });
        thread_line(out, t, r, "frame step (CD) s", [](const ThreadRuns& c) { return fixed(c.cd_seconds, 3); });
        thread_line(out, t, r, "serial share of the frame step",
                    [](const ThreadRuns& c) { return share_cell(c.serial_share); });
        thread_line(out, t, r, "parallel steps a frame",
                    [](const ThreadRuns& c) { return fixed(c.parallel_steps_per_frame, 1); });
        thread_line(out, t, r, "peak MB", [](const ThreadRuns& c) { return megabytes(c.peak_bytes); });
    }
    out << "\n";
}

nlohmann::ordered_json thread_runs_json(const ScaleRow& r) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const ThreadRuns& c : r.by_threads)
        out.push_back({{"threads", c.threads},
                       {"sim_seconds", rounded(c.sim_seconds, 6)},
                       {"cd_seconds", rounded(c.cd_seconds, 6)},
                       {"wall_seconds", rounded(c.wall_seconds, 3)},
                       {"peak_bytes", c.peak_bytes},
                       {"speedup", rounded(c.speedup, 3)},
                       {"serial_share", c.serial_share ? nlohmann::ordered_json(rounded(*c.serial_share, 4)) : nullptr},
                       {"parallel_steps_per_frame", rounded(c.parallel_steps_per_frame, 2)},
                       {"digest", c.digest}});
    return out;
}

}  // namespace

std::string table_markdown(const BenchTable& t) {
    std::ostringstream out;
    out << "### " << t.title << "\n\n"
        << "| Method | Time (us) | x sweep | #2D | #3D | #sample | positive | differs from brute force |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const MethodRow& r : t.rows) {
        if (!r.measured) {
            out << "| " << r.label << " | - | - | - | - | - | - | - (" << r.note << ") |\n";
            continue;
        }
        out << "| " << r.label << " | " << fixed(r.us_per_query, 3) << " | " << ratio_cell(r) << " | "
            << fixed(r.tests2d, 2) << " | " << fixed(r.tests3d, 2) << " | " << fixed(r.samples, 2) << " | "
            << fixed(100.0 * r.positive, 1) << " % | " << r.disagreements << disagreement_split(r)
            << (r.note.empty() ? "" : " (" + r.note + ")") << " |\n";
    }
    out << "\n";
    targets_markdown(out, t.targets);
    for (const auto& [k, v] : t.notes) out << "- " << k << ": " << v << "\n";
    return out.str();
}

std::string table_json(const BenchTable& t) {
    nlohmann::ordered_json j;
    j["workload"] = t.workload;
    j["title"] = t.title;
    j["targets"] = targets_json(t.targets);
    j["notes"] = notes_json(t.notes);
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const MethodRow& r : t.rows)
        rows.push_back({{"method", r.label},
                        {"us_per_query", r.measured ? nlohmann::ordered_json(rounded(r.us_per_query, 4)) : nullptr},
                        {"x_sweep", rounded(r.x_sweep, 3)},
                        {"tests2d", rounded(r.tests2d, 4)},
                        {"tests3d", rounded(r.tests3d, 4)},
                        {"samples", rounded(r.samples, 4)},
                        {"positive", rounded(r.positive, 6)},
                        {"queries", r.queries},
                        {"timed_queries", r.timed_queries},
                        {"disagreements", r.disagreements},
                        {"extra_positives", r.extra},
                        {"missed_positives", r.missed},
                        {"measured", r.measured},
                        {"default", r.method == kDefaultMethod},
                        {"note", r.note}});
    j["rows"] = rows;
    return readable_json(j);
}

void write_table_png(const BenchTable& t, const std::string& file) {
    std::vector<Bar> bars;
    for (const MethodRow& r : t.rows)
        if (r.measured) bars.push_back({r.label, r.us_per_query});
    write_bar_chart(file, t.title, bars, "us/query");
}

std::string scale_markdown(const ScaleTable& t) {
    std::ostringstream out;
    const std::string one = threads_label(t.threads.empty() ? 1 : t.threads.front());
    const std::string n = threads_label(t.rows.empty() ? 0 : t.rows.front().threads);
    out << "### " << t.title << "\n\n"
        << "| agents | world (m) | choice points | queries | CD s (" << one
        << ") | CD us / agent / sim s | x N=" << (t.rows.empty() ? 0 : t.rows.front().agents)
        << " | CD us / query | sim s (" << one << ") | sim s (" << n
        << ") | speed-up | identical | fallbacks | contacts outside fallbacks | peak MB (" << one << ") | peak MB ("
        << n << ") | wall s (" << n << ") |\n"
        << "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|\n";
    for (const ScaleRow& r : t.rows)
        out << "| " << r.agents << " | " << fixed(r.width, 1) << " x " << fixed(r.height, 1) << " | " << r.choice_points
            << " | " << r.queries << " | " << one_thread_cell(r, r.cd_seconds_1, 3) << " | "
            << fixed(r.cd_us_per_agent_second, 3) << " | " << one_thread_cell(r, r.ratio_to_first, 2) << " | "
            << fixed(r.cd_us_per_query, 3) << " | " << one_thread_cell(r, r.sim_seconds_1, 3) << " | "
            << fixed(r.sim_seconds_n, 3) << " | " << one_thread_cell(r, r.speedup, 2) << " | "
            << (r.identical ? "yes" : "NO") << " | " << r.fallbacks << " | " << r.contacts_unexcused << " | "
            << (r.one_thread ? megabytes(r.peak_bytes_1) : "-") << " | " << megabytes(r.peak_bytes_n) << " | "
            << fixed(r.wall_seconds_n, 1) << " |\n";
    out << "\n";
    thread_table(out, t);
    targets_markdown(out, t.targets);
    for (const auto& [k, v] : t.notes) out << "- " << k << ": " << v << "\n";
    return out.str();
}

std::string scale_json(const ScaleTable& t) {
    nlohmann::ordered_json j;
    j["workload"] = "scale";
    j["title"] = t.title;
    j["targets"] = targets_json(t.targets);
    j["notes"] = notes_json(t.notes);
    j["threads"] = t.threads;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const ScaleRow& r : t.rows)
        rows.push_back({{"method", "crowd " + std::to_string(r.agents) + " agents"},
                        {"us_per_query", rounded(r.cd_us_per_query, 4)},
                        {"agents", r.agents},
                        {"world", {rounded(r.width, 3), rounded(r.height, 3)}},
                        {"choice_points", r.choice_points},
                        {"candidates", r.candidates},
                        {"queries", r.queries},
                        {"cd_seconds_1", rounded(r.cd_seconds_1, 6)},
                        {"cd_seconds_n", rounded(r.cd_seconds_n, 6)},
                        {"cd_us_per_agent_second", rounded(r.cd_us_per_agent_second, 4)},
                        {"ratio_to_first", rounded(r.ratio_to_first, 3)},
                        {"sim_seconds_1", rounded(r.sim_seconds_1, 6)},
                        {"sim_seconds_n", rounded(r.sim_seconds_n, 6)},
                        {"threads", r.threads},
                        {"speedup", rounded(r.speedup, 3)},
                        {"identical", r.identical},
                        {"digest_1", r.digest_1},
                        {"digest_n", r.digest_n},
                        {"fallbacks", r.fallbacks},
                        {"contacts_outside_fallbacks", r.contacts_unexcused},
                        {"one_thread", r.one_thread},
                        {"peak_bytes_1", r.peak_bytes_1},
                        {"peak_bytes_n", r.peak_bytes_n},
                        {"wall_seconds_1", rounded(r.wall_seconds_1, 3)},
                        {"wall_seconds_n", rounded(r.wall_seconds_n, 3)},
                        {"by_threads", thread_runs_json(r)}});
    j["rows"] = rows;
    return readable_json(j);
}

void write_scale_png(const ScaleTable& t, const std::string& file) {
    std::vector<Bar> bars;
    for (const ScaleRow& r : t.rows) bars.push_back({std::to_string(r.agents) + " agents", r.cd_us_per_agent_second});
    write_bar_chart(file, t.title, bars, "CD us / agent / simulated s");
}

}  // namespace mobb::bench
