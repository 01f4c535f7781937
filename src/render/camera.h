// An orbit camera around a target point in the GL world (y up): yaw and pitch in degrees.
#pragma once
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace mobb::render {

struct Ray {
    glm::vec3 origin, dir;
};

struct Camera {
    glm::vec3 target{0.0f};
    float yaw = 35.0f;       ///< degrees about the up axis; 0 looks along -z (from +z)
    float pitch = 25.0f;     ///< degrees above the ground
    float distance = 10.0f;  ///< metres from the target
    float fov = 35.0f;       ///< vertical field of view, degrees

    glm::vec3 eye() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;

    void orbit(float dx_degrees, float dy_degrees);
    /// Moves the target by a screen-space drag of (dx, dy) pixels in a viewport `height` pixels tall.
    void pan(float dx, float dy, float height);
    void zoom(float steps);  ///< positive steps move closer
    /// Keeps yaw and pitch, centres the GL-world box [lo, hi] and backs off to the nearest distance at which
    /// its eight corners are all in view (the viewport's aspect: width / height).
    void frame(const glm::vec3& lo, const glm::vec3& hi, float aspect);
    /// The same for a set of GL-world points (at least one): centres their box and backs off until every
    /// point is in view.
    void frame(const std::vector<glm::vec3>& points, float aspect);
    void top();   ///< looking straight down
    void side();  ///< looking horizontally along -z: x to the right, time up

    /// The ray through pixel (px, py), origin top-left, of a width x height viewport.
    Ray ray(float px, float py, float width, float height) const;
};

}  // namespace mobb::render
