#include "camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "mobb/core/assert.h"

namespace mobb::render {

glm::vec3 Camera::eye() const {
    const float y = glm::radians(yaw), p = glm::radians(pitch);
    return target + distance * glm::vec3(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
}

glm::mat4 Camera::view() const {
    // Looking straight down the up vector is singular: tilt the up vector with the yaw instead.
    const float y = glm::radians(yaw);
    const glm::vec3 up = pitch > 89.0f ? glm::vec3(-std::sin(y), 0.0f, -std::cos(y)) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(eye(), target, up);
}

glm::mat4 Camera::projection(float aspect) const {
    const float near_plane = std::max(0.01f, distance * 0.01f);
    return glm::perspective(glm::radians(fov), aspect, near_plane, distance * 20.0f + 100.0f);
}

void Camera::orbit(float dx_degrees, float dy_degrees) {
    yaw -= dx_degrees;
    pitch = std::clamp(pitch + dy_degrees, -89.0f, 89.9f);
}

void Camera::pan(float dx, float dy, float height) {
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
    const float metres_per_pixel = 2.0f * distance * std::tan(glm::radians(fov) * 0.5f) / std::max(height, 1.0f);
    target += (-dx * right + dy * up) * metres_per_pixel;
}

void Camera::zoom(float steps) { distance = std::clamp(distance * std::pow(0.88f, steps), 0.05f, 5000.0f); }

void Camera::frame(const glm::vec3& lo, const glm::vec3& hi, float aspect) {
    std::vector<glm::vec3> corners;
    corners.reserve(8);
    for (int k = 0; k < 8; ++k)
        corners.emplace_back((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    frame(corners, aspect);
}

void Camera::frame(const std::vector<glm::vec3>& points, float aspect) {
    MOBB_ASSERT(aspect > 0.0f && !points.empty());
    glm::vec3 lo = points.front(), hi = points.front();
    for (const glm::vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    target = 0.5f * (lo + hi);
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]), back(v[0][2], v[1][2], v[2][2]);
    const float tan_y = std::tan(glm::radians(fov) * 0.5f), tan_x = tan_y * aspect;
    // The nearest eye from which the view's frustum holds every point: a point at (x, y) across the view
    // and z towards the eye needs distance >= z + |x| / tan(half fov x), likewise in y.
    auto fit = [&] {
        float nearest = 0.5f;
        for (const glm::vec3& p : points) {
            const glm::vec3 rel = p - target;
            const float z = glm::dot(rel, back);
            nearest = std::max(
                {nearest, z + std::abs(glm::dot(rel, right)) / tan_x, z + std::abs(glm::dot(rel, up)) / tan_y});
        }
        distance = nearest;
    };
    // Perspective draws the near side larger: the box's centre is not the picture's. A few steps move the
    // target across the view until the points' picture is centred, then fit again.
    constexpr int kCentring = 4;
    for (int k = 0; k < kCentring; ++k) {
        fit();
        float x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
        for (const glm::vec3& p : points) {
            const glm::vec3 rel = p - target;
            const float depth = distance - glm::dot(rel, back);  // in front of the eye: fit() keeps it positive
            const float x = glm::dot(rel, right) / (depth * tan_x), y = glm::dot(rel, up) / (depth * tan_y);
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
        target += distance * (0.5f * (x0 + x1) * tan_x * right + 0.5f * (y0 + y1) * tan_y * up);
    }
    fit();
}

void Camera::top() {
    pitch = 89.9f;
    yaw = 0.0f;
}

void Camera::side() {
    pitch = 0.0f;
    yaw = 0.0f;
}

Ray Camera::ray(float px, float py, float width, float height) const {
    const glm::mat4 inv = glm::inverse(projection(width / std::max(height, 1.0f)) * view());
    const float x = 2.0f * px / width - 1.0f, y = 1.0f - 2.0f * py / height;
    glm::vec4 a = inv * glm::vec4(x, y, -1.0f, 1.0f), b = inv * glm::vec4(x, y, 1.0f, 1.0f);
    a /= a.w;
    b /= b.w;
    return {glm::vec3(a), glm::normalize(glm::vec3(b - a))};
}

}  // namespace mobb::render
