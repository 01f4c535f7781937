// Query sets as text files (query_set.h).
#include <fstream>
#include <stdexcept>

#include "query_set.h"

namespace mobb::bench {

namespace {

void write_placement(std::ostream& out, const Placement& p) {
    out << ' ' << p.x << ' ' << p.y << ' ' << p.theta << ' ' << p.t0;
}
bool read_placement(std::istream& in, Placement& p) { return bool(in >> p.x >> p.y >> p.theta >> p.t0); }

void expect(std::istream& in, const std::string& word, const std::string& file) {
    std::string got;
    if (!(in >> got) || got != word) throw std::runtime_error(file + ": expected '" + word + "'");
}

}  // namespace

void save_query_set(const QuerySet& set, const std::string& file) {
    std::ofstream out(file);
    out.precision(17);
    out << "mobb query set 1\nclips " << set.clips.size() << "\n";
    for (const Path& p : set.clips) {
        out << "clip " << p.dt << ' ' << p.size() << "\n";
        for (const Sample& s : p.samples) out << s.x << ' ' << s.y << ' ' << s.r << "\n";
    }
    out << "queries " << set.queries.size() << "\n";
    for (const ClipQuery& q : set.queries) {
        out << q.a << ' ' << q.b;
        write_placement(out, q.pa);
        write_placement(out, q.pb);
        out << "\n";
    }
    if (!out) throw std::runtime_error(file + ": cannot write");
}

QuerySet load_query_set(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open");
    for (const char* w : {"mobb", "query", "set", "1", "clips"}) expect(in, w, file);
    std::size_t clips = 0, queries = 0;
    if (!(in >> clips)) throw std::runtime_error(file + ": bad clip count");
    QuerySet set;
    set.clips.resize(clips);
    for (Path& p : set.clips) {
        std::size_t n = 0;
        expect(in, "clip", file);
        if (!(in >> p.dt >> n)) throw std::runtime_error(file + ": bad clip header");
        p.samples.resize(n);
        for (Sample& s : p.samples)
            if (!(in >> s.x >> s.y >> s.r)) throw std::runtime_error(file + ": bad sample");
    }
    expect(in, "queries", file);
    if (!(in >> queries)) throw std::runtime_error(file + ": bad query count");
    set.queries.resize(queries);
    for (ClipQuery& q : set.queries) {
        if (!(in >> q.a >> q.b) || !read_placement(in, q.pa) || !read_placement(in, q.pb))
            throw std::runtime_error(file + ": bad query");
        if (q.a < 0 || q.b < 0 || std::size_t(q.a) >= clips || std::size_t(q.b) >= clips)
            throw std::runtime_error(file + ": clip id out of range");
    }
    return set;
}

}  // namespace mobb::bench
