// mobb query A B and mobb batch: yes/no collision queries between placed clips (batch: on a worker pool).
#include <array>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "mobb/core/angle.h"
#include "mobb/core/brute.h"
#include "mobb/core/query.h"
#include "mobb/util/worker_pool.h"

namespace mobb::app {

namespace {

nlohmann::ordered_json answer_json(bool hit, const QueryStats& stats) {
    nlohmann::ordered_json j;
    j["collide"] = hit;
    j["tests2d"] = stats.tests2d;
    j["tests3d"] = stats.tests3d;
    j["samples"] = stats.samples;
    return j;
}

// One query with its clips resolved: read-only, so queries can run on any thread.
struct Job {
    const Path* path_a = nullptr;
    const Path* path_b = nullptr;
    const Tree* tree_a = nullptr;  // null for brute force
    const Tree* tree_b = nullptr;
    Placement pa, pb;
};

Job resolve(ClipCache& cache, bool brute, const std::string& a, const Placement& pa, const std::string& b,
            const Placement& pb) {
    Job job;
    job.pa = pa;
    job.pb = pb;
    if (brute) {
        job.path_a = &cache.clip(a).path;
        job.path_b = &cache.clip(b).path;
    } else {
        job.tree_a = &cache.tree(a);
        job.tree_b = &cache.tree(b);
    }
    return job;
}

nlohmann::ordered_json answer(const Job& job) {
    QueryStats stats;
    const bool hit = job.tree_a ? collide(*job.tree_a, job.pa, *job.tree_b, job.pb, &stats)
                                : collide_brute(*job.path_a, job.pa, *job.path_b, job.pb, &stats);
    return answer_json(hit, stats);
}

Placement placement_of(const nlohmann::json& v, const std::string& where) {
    if (!v.is_array() || v.size() != 4) throw InputError(where + ": expected [x, y, theta, t0]");
    double x[4];
    for (int k = 0; k < 4; ++k) {
        if (!v[std::size_t(k)].is_number()) throw InputError(where + ": expected numbers");
        x[k] = v[std::size_t(k)].get<double>();
        if (!std::isfinite(x[k])) throw InputError(where + ": not finite");
    }
    return {x[0], x[1], radians(x[2]), x[3]};
}

std::string file_of(const nlohmann::json& line, const char* key, const std::string& where) {
    if (!line.contains(key) || !line[key].is_string())
        throw InputError(where + ": \"" + key + "\" must be a file name");
    return line[key].get<std::string>();
}

// The job of one input line, or nothing for a blank line. Throws InputError naming the line.
std::optional<Job> parse_line(const std::string& text, int n, ClipCache& cache, bool brute) {
    const std::string where = "stdin:" + std::to_string(n);
    if (text.find_first_not_of(" \t\r") == std::string::npos) return std::nullopt;
    const nlohmann::json line = nlohmann::json::parse(text, nullptr, false);
    if (line.is_discarded() || !line.is_object()) throw InputError(where + ": not a JSON object");
    const std::string a = file_of(line, "a", where), b = file_of(line, "b", where);
    if (!line.contains("ta") || !line.contains("tb")) throw InputError(where + ": \"ta\" and \"tb\" are required");
    const Placement pa = placement_of(line["ta"], where + ": ta"), pb = placement_of(line["tb"], where + ": tb");
    return resolve(cache, brute, a, pa, b, pb);
}

// Lines are read, checked and their clips loaded in order on this thread (so the first bad line is
// the one reported); the queries of a chunk of lines then run on the pool and print in input order.
void run_batch(std::istream& in, std::ostream& out, ClipCache& cache, bool brute, util::WorkerPool& pool) {
    constexpr std::size_t kChunk = 1 << 14;  // lines held at once
    std::vector<Job> jobs;
    std::vector<std::string> answers;
    auto flush = [&] {
        answers.resize(jobs.size());
        pool.for_each(
            jobs.size(), [&](std::size_t k, int) { answers[k] = answer(jobs[k]).dump(); }, 16);
        for (const std::string& a : answers) out << a << "\n";
        jobs.clear();
    };
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
        if (std::optional<Job> job = parse_line(text, n, cache, brute)) jobs.push_back(*job);
        if (jobs.size() == kChunk) flush();
    }
    flush();
}

}  // namespace

void add_query(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("query", "Do two placed clips ever collide? Prints one JSON object");
    auto files = std::make_shared<std::vector<std::string>>();
    auto place = std::make_shared<std::array<std::string, 2>>();
    auto load = std::make_shared<LoadArgs>();
    auto tree = std::make_shared<TreeArgs>();
    cmd->add_option("A B", *files, "Two BVH or glTF/GLB files")->required()->expected(2);
    cmd->add_option("--place-a", (*place)[0], "Placement of A: x,y,theta,t0 (m, m, degrees, s)")->required();
    cmd->add_option("--place-b", (*place)[1], "Placement of B: x,y,theta,t0 (m, m, degrees, s)")->required();
    load->add_to(*cmd);
    tree->add_to(*cmd, true);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            const Placement pa = parse_placement((*place)[0], "--place-a");
            const Placement pb = parse_placement((*place)[1], "--place-b");
            ClipCache cache(load->options(), tree->options());
            out << answer(resolve(cache, tree->brute(), (*files)[0], pa, (*files)[1], pb)).dump() << "\n";
        });
    });
}

void add_batch(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "batch", "Answer JSON lines {\"a\": FILE, \"b\": FILE, \"ta\": [x,y,theta,t0], \"tb\": [...]} from stdin");
    auto load = std::make_shared<LoadArgs>();
    auto tree = std::make_shared<TreeArgs>();
    auto threads = std::make_shared<int>(util::WorkerPool::hardware_threads());
    load->add_to(*cmd);
    tree->add_to(*cmd, true);
    cmd->add_option("--threads", *threads, "Worker threads (the output is the same for any count)")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            ClipCache cache(load->options(), tree->options());
            util::WorkerPool pool(*threads);
            run_batch(std::cin, out, cache, tree->brute(), pool);
        });
    });
}

}  // namespace mobb::app
