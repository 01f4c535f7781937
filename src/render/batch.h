// A growable list of coloured vertices drawn as lines or triangles with the color shader: grid,
// box edges and faces, skeletons, the cursor plane, text.
#pragma once
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl.h"

namespace mobb::render {

struct ColorVertex {
    glm::vec3 pos;
    glm::vec4 color;
};

class Batch {
public:
    explicit Batch(GLenum mode);  ///< GL_LINES or GL_TRIANGLES
    ~Batch();
    Batch(const Batch&) = delete;
    Batch& operator=(const Batch&) = delete;

    void clear() {
        vertices_.clear();
        dirty_ = true;
    }
    void line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color);
    void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec4& color);
    /// A colour per vertex (shaded surfaces), interpolated across the triangle.
    void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec4& ca, const glm::vec4& cb,
                  const glm::vec4& cc);
    void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d, const glm::vec4& color);
    bool empty() const { return vertices_.empty(); }

    /// Uploads the vertices (when changed since the last upload) and draws them; the caller binds the program.
    void draw();

private:
    GLenum mode_;
    GLuint vao_ = 0, vbo_ = 0;
    std::vector<ColorVertex> vertices_;
    bool dirty_ = true;  ///< vertices changed since the last upload
};

}  // namespace mobb::render
