#include "batch.h"

#include "draw_counts.h"

#include <cstddef>

namespace mobb::render {

Batch::Batch(GLenum mode) : mode_(mode) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ColorVertex),
                          reinterpret_cast<void*>(offsetof(ColorVertex, pos)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ColorVertex),
                          reinterpret_cast<void*>(offsetof(ColorVertex, color)));
    glBindVertexArray(0);
}

Batch::~Batch() {
    glDeleteBuffers(1, &vbo_);
    glDeleteVertexArrays(1, &vao_);
}

void Batch::line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color) {
    vertices_.push_back({a, color});
    vertices_.push_back({b, color});
    dirty_ = true;
}

void Batch::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec4& ca,
                     const glm::vec4& cb, const glm::vec4& cc) {
    vertices_.push_back({a, ca});
    vertices_.push_back({b, cb});
    vertices_.push_back({c, cc});
    dirty_ = true;
}

void Batch::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec4& color) {
    vertices_.push_back({a, color});
    vertices_.push_back({b, color});
    vertices_.push_back({c, color});
    dirty_ = true;
}

void Batch::quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                 const glm::vec4& color) {
    triangle(a, b, c, color);
    triangle(a, c, d, color);
}

void Batch::draw() {
    if (vertices_.empty()) return;
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    if (dirty_) {
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices_.size() * sizeof(ColorVertex)), vertices_.data(),
                     GL_DYNAMIC_DRAW);
        dirty_ = false;
    }
    glDrawArrays(mode_, 0, GLsizei(vertices_.size()));
    count_draw(vertices_.size());
    glBindVertexArray(0);
}

}  // namespace mobb::render
