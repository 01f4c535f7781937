#include "timing.h"

#include <algorithm>
#include <chrono>

#include "mobb/util/median.h"

namespace mobb::bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The untimed pass of one method: answers (the first `count` queries), tests, positives.
MethodRow count_pass(const QuerySet& set, const QueryMethod& m, std::size_t count, std::vector<bool>& answers) {
    QueryStats st;
    std::uint64_t pos = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const ClipQuery& q = set.queries[k];
        const bool hit = m.query(q.a, q.pa, q.b, q.pb, &st);
        answers.push_back(hit);
        pos += hit;
    }
    MethodRow r;
    r.method = m.method();
    r.label = label(m.method());
    r.queries = count;
    const double d = double(std::max<std::size_t>(1, count));
    r.tests2d = double(st.tests2d) / d;
    r.tests3d = double(st.tests3d) / d;
    r.samples = double(st.samples) / d;
    r.positive = double(pos) / d;
    r.note = m.note();
    return r;
}

// One timed pass of one method over the first `count` queries: microseconds per query.
double timed_pass(const QuerySet& set, const QueryMethod& m, std::size_t count) {
    static volatile bool sink = false;
    const auto t0 = Clock::now();
    bool acc = false;
    for (std::size_t k = 0; k < count; ++k) {
        const ClipQuery& q = set.queries[k];
        acc ^= m.query(q.a, q.pa, q.b, q.pb, nullptr);
    }
    const double us = seconds_since(t0) * 1e6 / double(std::max<std::size_t>(1, count));
    sink = sink ^ acc;
    return us;
}

std::size_t index_of(const std::vector<MethodRow>& rows, Method m) {
    for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows[k].method == m && rows[k].measured) return k;
    return rows.size();
}

// Disagreements with the brute-force row (over the queries both answered) and ratios to the sweep's.
void compare_rows(std::vector<MethodRow>& rows, const std::vector<std::vector<bool>>& answers) {
    const std::size_t ref = index_of(rows, Method::Brute), sweep = index_of(rows, Method::Sweep);
    for (std::size_t m = 0; m < rows.size(); ++m) {
        if (ref < rows.size()) {
            const std::size_t n = std::min(answers[m].size(), answers[ref].size());
            for (std::size_t k = 0; k < n; ++k) {
                rows[m].extra += answers[m][k] && !answers[ref][k];
                rows[m].missed += !answers[m][k] && answers[ref][k];
            }
            rows[m].disagreements = rows[m].extra + rows[m].missed;
        }
        if (sweep < rows.size() && rows[sweep].us_per_query > 0 && rows[m].measured)
            rows[m].x_sweep = rows[m].us_per_query / rows[sweep].us_per_query;
    }
}

}  // namespace

std::function<void(double)> progress_stage(const std::function<void(double)>& p, double lo, double hi) {
    if (!p) return {};
    return [p, lo, hi](double f) { p(lo + (hi - lo) * std::clamp(f, 0.0, 1.0)); };
}

const MethodRow* find_row(const std::vector<MethodRow>& rows, Method method) {
    for (const MethodRow& r : rows)
        if (r.method == method && r.measured && r.us_per_query > 0) return &r;
    return nullptr;
}

std::vector<MethodRow> time_methods(const QuerySet& set, const std::vector<std::unique_ptr<QueryMethod>>& methods,
                                    int passes, const std::function<void(double)>& progress, std::size_t slow_queries) {
    const std::size_t n = set.queries.size(), nm = methods.size();
    std::vector<MethodRow> rows(nm);
    std::vector<std::vector<bool>> answers(nm);
    std::vector<std::size_t> timed(nm, 0);
    for (std::size_t m = 0; m < nm; ++m) {
        const QueryMethod& qm = *methods[m];
        if (!qm.unavailable().empty()) {
            rows[m].method = qm.method();
            rows[m].label = label(qm.method());
            rows[m].measured = false;
            rows[m].note = qm.unavailable();
            continue;
        }
        methods[m]->prepare(set.clips);
        timed[m] = qm.slow() ? std::min(n, slow_queries) : n;
        const bool reference = qm.method() == Method::Brute;
        rows[m] = count_pass(set, qm, reference ? n : timed[m], answers[m]);
        rows[m].timed_queries = timed[m];
        if (timed[m] < n)
            rows[m].note += std::string(rows[m].note.empty() ? "" : "; ") + "timed on the first " +
                            std::to_string(timed[m]) + " queries";
        if (progress) progress(0.2 * double(m + 1) / double(nm));
    }
    std::vector<std::vector<double>> times(nm);
    for (int p = 0; p < passes; ++p)
        for (std::size_t m = 0; m < nm; ++m) {
            if (rows[m].measured) times[m].push_back(timed_pass(set, *methods[m], timed[m]));
            if (progress) progress(0.2 + 0.8 * double(std::size_t(p) * nm + m + 1) / double(std::size_t(passes) * nm));
        }
    for (std::size_t m = 0; m < nm; ++m) rows[m].us_per_query = util::median(times[m]);
    compare_rows(rows, answers);
    return rows;
}

}  // namespace mobb::bench
