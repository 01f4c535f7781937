#include "method.h"

#include <stdexcept>

#include "mobb/core/brute.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/obb.h"
#include "mobb/core/scan.h"
#include "mobb/core/sweep.h"

namespace mobb::bench {

namespace {

struct PeerName {
    Method method;
    const char* key;
    const char* label;
};
// The methods after the trees (whose names are the core's tree-type table).
constexpr PeerName kPeers[] = {
    {Method::Brute, "brute", "brute force"},
    {Method::Scan, "scan", "best scan"},
    {Method::Sweep, "sweep", "circle sweep"},
    {Method::Fcl, "fcl", "FCL"},
};
static_assert(kTreeTypeCount + int(sizeof kPeers / sizeof kPeers[0]) == kMethodCount, "one name per method");

const PeerName& peer(Method m) { return kPeers[int(m) - kTreeTypeCount]; }

class TreeMethod : public QueryMethod {
public:
    TreeMethod(TreeType type, int n_min) : type_(type), n_min_(n_min) {}
    Method method() const override { return Method(int(type_)); }
    void prepare(const std::vector<Path>& clips) override {
        trees_.clear();
        for (const Path& p : clips) trees_.push_back(Tree::build(p, {type_, n_min_}));
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
    Method method() const override { return Method::Brute; }
    bool slow() const override { return true; }
    void prepare(const std::vector<Path>& clips) override { paths_ = clips; }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats) const override {
        return collide_brute(paths_[std::size_t(a)], pa, paths_[std::size_t(b)], pb, stats);
    }

private:
    std::vector<Path> paths_;
};

// The circle sweep (collide_sweep) or the best scan (collide_scan) on one ClipIndex per clip.
class IndexMethod : public QueryMethod {
public:
    explicit IndexMethod(bool sweep) : sweep_(sweep) {}
    Method method() const override { return sweep_ ? Method::Sweep : Method::Scan; }
    void prepare(const std::vector<Path>& clips) override {
        index_.clear();
        for (const Path& p : clips) index_.push_back(ClipIndex::build(p));
    }
    bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats*) const override {
        const ClipIndex &ia = index_[std::size_t(a)], &ib = index_[std::size_t(b)];
        return sweep_ ? collide_sweep(ia, pa, ib, pb) : collide_scan(ia, pa, ib, pb);
    }

private:
    bool sweep_;
    std::vector<ClipIndex> index_;
};

}  // namespace

const char* key(Method m) { return tree_type(m) ? to_string(*tree_type(m)) : peer(m).key; }

const char* label(Method m) { return tree_type(m) ? mobb::label(*tree_type(m)) : peer(m).label; }

std::optional<TreeType> tree_type(Method m) {
    if (int(m) < kTreeTypeCount) return TreeType(int(m));
    return std::nullopt;
}

Method parse_method(const std::string& name) {
    std::string keys;
    for (int k = 0; k < kMethodCount; ++k) {
        const Method m = Method(k);
        if (name == key(m) || name == label(m)) return m;
        keys += (k ? ", " : "") + std::string(key(m));
    }
    throw std::invalid_argument("unknown method '" + name + "' (" + keys + ")");
}

std::vector<Method> paper_methods() {
    return {Method::Mobb1,   Method::Umobb1,  Method::Mobb, Method::Umobb,
            Method::Hybrid1, Method::Hybrid2, Method::Brute};
}

std::vector<Method> table_methods() {
    std::vector<Method> out = paper_methods();
    for (Method m : {Method::Scan, Method::Fcl, Method::Sweep}) out.push_back(m);
    return out;
}

std::unique_ptr<QueryMethod> make_method(Method m, int n_min) {
    if (const auto type = tree_type(m)) return std::make_unique<TreeMethod>(*type, n_min);
    switch (m) {
        case Method::Brute: return std::make_unique<BruteMethod>();
        case Method::Scan: return std::make_unique<IndexMethod>(false);
        case Method::Sweep: return std::make_unique<IndexMethod>(true);
        default: return fcl_method();
    }
}

std::vector<std::unique_ptr<QueryMethod>> make_methods(const std::vector<Method>& methods, int n_min) {
    std::vector<std::unique_ptr<QueryMethod>> out;
    out.reserve(methods.size());
    for (Method m : methods) out.push_back(make_method(m, n_min));
    return out;
}

bool root_boxes_overlap(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb) {
    return overlap(transformed(a.box3(a.root()), SpaceTimeRigid::of(pa)),
                   transformed(b.box3(b.root()), SpaceTimeRigid::of(pb)));
}

}  // namespace mobb::bench
