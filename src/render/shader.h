// GLSL programs built from the embedded copies of shaders/*.vert and *.frag.
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl.h"

namespace mobb::render {

/// Source text of one file of shaders/ (embedded at build time), or null.
const char* shader_source(const char* name);

class Program {
public:
    /// Compiles and links two embedded shaders; throws std::runtime_error with the GL log on failure.
    Program(const char* vertex, const char* fragment);
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const { glUseProgram(id_); }
    void set(const char* name, const glm::mat4& m) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, float v) const;
    void set(const char* name, int v) const;
    void set(const char* name, const glm::vec3* v, int count) const;  ///< a uniform array

private:
    GLuint id_ = 0;
};

}  // namespace mobb::render
