#include "fcl_peer.h"

#include <cmath>
#include <vector>

#include <fcl/fcl.h>

#include "mobb/core/angle.h"

namespace mobb::bench {

struct FclClip::Impl {
    std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> model;
};

FclClip::FclClip(const Path& path, int sides) : impl_(std::make_unique<Impl>()) {
    const double grow = 1.0 / std::cos(kPi / sides);
    std::vector<fcl::Vector3d> vertices;
    std::vector<fcl::Triangle> triangles;
    vertices.reserve(path.size() * std::size_t(2 * sides));
    triangles.reserve(path.size() * std::size_t(4 * sides - 4));
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Sample& s = path.samples[i];
        const double t0 = double(i) * path.dt, t1 = double(i + 1) * path.dt;
        const auto base = vertices.size();
        for (int k = 0; k < sides; ++k) {
            const double a = 2 * kPi * k / sides;
            const double x = s.x + s.r * grow * std::cos(a), y = s.y + s.r * grow * std::sin(a);
            vertices.emplace_back(x, y, t0);
            vertices.emplace_back(x, y, t1);
        }
        const auto v = [&](int k, int top) { return base + std::size_t(2 * (k % sides) + top); };
        for (int k = 0; k < sides; ++k) {  // side quads
            triangles.emplace_back(v(k, 0), v(k + 1, 0), v(k + 1, 1));
            triangles.emplace_back(v(k, 0), v(k + 1, 1), v(k, 1));
        }
        for (int k = 1; k + 1 < sides; ++k) {  // caps as fans
            triangles.emplace_back(v(0, 0), v(k + 1, 0), v(k, 0));
            triangles.emplace_back(v(0, 1), v(k, 1), v(k + 1, 1));
        }
    }
    impl_->model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    impl_->model->beginModel(int(triangles.size()), int(vertices.size()));
    impl_->model->addSubModel(vertices, triangles);
    impl_->model->endModel();
}

FclClip::~FclClip() = default;
FclClip::FclClip(FclClip&&) noexcept = default;
FclClip& FclClip::operator=(FclClip&&) noexcept = default;

std::size_t FclClip::triangles() const { return std::size_t(impl_->model->num_tris); }

namespace {

fcl::Transform3d transform(const Placement& p) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = fcl::AngleAxisd(p.theta, fcl::Vector3d::UnitZ()).toRotationMatrix();
    tf.translation() = fcl::Vector3d(p.x, p.y, p.t0);
    return tf;
}

}  // namespace

bool fcl_collide(const FclClip& a, const Placement& pa, const FclClip& b, const Placement& pb) {
    fcl::CollisionRequestd request(1, false);
    fcl::CollisionResultd result;
    fcl::collide(a.impl_->model.get(), transform(pa), b.impl_->model.get(), transform(pb), request, result);
    return result.isCollision();
}

bool fcl_available() { return true; }

}  // namespace mobb::bench
