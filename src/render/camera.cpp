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
    MOBB_ASSERT(aspect > 0.0f);
    target = 0.5f * (lo + hi);
    // The nearest eye from which the view's frustum holds all eight corners: a corner at (x, y) across
    // the view and z towards the eye needs distance >= z + |x| / tan(half fov x), likewise in y.
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]), back(v[0][2], v[1][2], v[2][2]);
    const float tan_y = std::tan(glm::radians(fov) * 0.5f), tan_x = tan_y * aspect;
    float nearest = 0.5f;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const glm::vec3 rel = corner - target;
        const float z = glm::dot(rel, back);
        nearest =
            std::max({nearest, z + std::abs(glm::dot(rel, right)) / tan_x, z + std::abs(glm::dot(rel, up)) / tan_y});
    }
    distance = nearest;
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
