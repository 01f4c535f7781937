#include "mobb/crowd/query_methods.h"

#include <cmath>
#include <stdexcept>

#include "mobb/core/brute.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/fast_query.h"
#include "mobb/core/scan.h"
#include "mobb/core/obb.h"

namespace mobb::crowd {

namespace {

const char* row_name(TreeType t) {
    switch (t) {
        case TreeType::Mobb1: return "MOBB 1 level";
        case TreeType::Umobb1: return "UMOBB 1 level";
        case TreeType::Mobb: return "MOBB";
        case TreeType::Umobb: return "UMOBB";
        case TreeType::Hybrid1: return "Hybrid 1";
        case TreeType::Hybrid2: return "Hybrid 2";
    }
    return "?";
}

class TreeMethod : public QueryMethod {
public:
    TreeMethod(TreeType type, int n_min) : type_(type), n_min_(n_min) {}
    std::string name() const override { return row_name(type_); }
    void prepare(const std::vector<Path>& clips) override {
        trees_.clear();
        TreeOptions o;
        o.type = type_;
        o.n_min = n_min_;
        for (const Path& p : clips) trees_.push_back(Tree::build(p, o));
    }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats) const override {
        return collide(trees_[std::size_t(a)], pa, trees_[std::size_t(b)], pb, stats);
    }

private:
    TreeType type_;
    int n_min_;
    std::vector<Tree> trees_;
};

class BruteMethod : public QueryMethod {
public:
    std::string name() const override { return "brute force"; }
    bool slow() const override { return true; }
    void prepare(const std::vector<Path>& clips) override { paths_ = clips; }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats) const override {
        return collide_brute(paths_[std::size_t(a)], pa, paths_[std::size_t(b)], pb, stats);
    }

private:
    std::vector<Path> paths_;
};

// mobb (collide_fast) or the best scan (collide_scan) on one ClipIndex per clip.
class IndexMethod : public QueryMethod {
public:
    explicit IndexMethod(bool fast) : fast_(fast) {}
    std::string name() const override { return fast_ ? "mobb" : "best scan"; }
    void prepare(const std::vector<Path>& clips) override {
        index_.clear();
        for (const Path& p : clips) index_.push_back(ClipIndex::build(p));
    }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats*) const override {
        const ClipIndex &ia = index_[std::size_t(a)], &ib = index_[std::size_t(b)];
        return fast_ ? collide_fast(ia, pa, ib, pb) : collide_scan(ia, pa, ib, pb);
    }

private:
    bool fast_;
    std::vector<ClipIndex> index_;
};

SpaceTimeRigid rigid_of(const Placement& p) { return {std::cos(p.theta), std::sin(p.theta), {p.x, p.y, p.t0}}; }

}  // namespace

std::unique_ptr<QueryMethod> tree_method(TreeType type, int n_min) { return std::make_unique<TreeMethod>(type, n_min); }
std::unique_ptr<QueryMethod> brute_method() { return std::make_unique<BruteMethod>(); }
std::unique_ptr<QueryMethod> mobb_method() { return std::make_unique<IndexMethod>(true); }
std::unique_ptr<QueryMethod> scan_method() { return std::make_unique<IndexMethod>(false); }

std::vector<std::unique_ptr<QueryMethod>> paper_methods(int n_min) {
    std::vector<std::unique_ptr<QueryMethod>> out;
    for (TreeType t : {TreeType::Mobb1, TreeType::Umobb1, TreeType::Mobb, TreeType::Umobb, TreeType::Hybrid1, TreeType::Hybrid2})
        out.push_back(tree_method(t, n_min));
    out.push_back(brute_method());
    return out;
}

std::vector<std::unique_ptr<QueryMethod>> bench_methods(int n_min) {
    std::vector<std::unique_ptr<QueryMethod>> out = paper_methods(n_min);
    out.push_back(scan_method());
    out.push_back(fcl_method());
    out.push_back(mobb_method());
    return out;
}

std::unique_ptr<QueryMethod> method_by_name(const std::string& name, int n_min) {
    for (auto& m : bench_methods(n_min))
        if (m->name() == name) return std::move(m);
    throw std::invalid_argument("unknown method '" + name + "'");
}

bool roots_overlap(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb) {
    return overlap(transformed(a.box3(a.root()), rigid_of(pa)), transformed(b.box3(b.root()), rigid_of(pb)));
}

}  // namespace mobb::crowd
