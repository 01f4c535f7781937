#include "targets.h"

#include <algorithm>
#include <cmath>

#include "mobb/util/json_text.h"

namespace mobb::bench {

Target speed_target(const std::vector<MethodRow>& rows, Method peer, double goal) {
    Target g;
    g.what = std::string(label(Method::Sweep)) + " >= " + util::fixed(goal, 0) + "x faster than " + label(peer);
    g.goal = goal;
    const MethodRow *m = find_row(rows, Method::Sweep), *p = find_row(rows, peer);
    if (!m || !p) {
        g.known = false;
        g.detail = std::string("no measured ") + label(m ? peer : Method::Sweep) + " row";
        return g;
    }
    g.measured = p->us_per_query / m->us_per_query;
    g.detail = util::fixed(p->us_per_query, 3) + " us / " + util::fixed(m->us_per_query, 3) + " us per query";
    return g;
}

std::string target_text(const Target& t) {
    using util::fixed;
    if (!t.known) return "not measured";
    const std::string rel = t.at_most ? "<= " : ">= ";
    const auto number = [](double x) { return fixed(x, x == std::floor(x) ? 0 : 2); };  // counts stay whole
    if (!t.ratio)
        return "measured " + number(t.measured) + ", goal " + rel + number(t.goal) + ": " +
               (t.met() ? "met" : "MISSED");
    std::string s = "measured " + fixed(t.measured, 2) + "x, goal " + rel + fixed(t.goal, 1) + "x: ";
    if (t.met()) return s + "met";
    const double gap = t.at_most ? t.measured / t.goal : t.goal / std::max(t.measured, 1e-12);
    return s + "MISSED (" + fixed(gap, 2) + "x short)";
}

Target at_most(const std::string& what, double goal, double measured, const std::string& detail, bool ratio) {
    Target t;
    t.what = what;
    t.goal = goal;
    t.measured = measured;
    t.at_most = true;
    t.ratio = ratio;
    t.detail = detail;
    return t;
}

Target at_least(const std::string& what, double goal, double measured, const std::string& detail) {
    Target t;
    t.what = what;
    t.goal = goal;
    t.measured = measured;
    t.detail = detail;
    return t;
}

}  // namespace mobb::bench
