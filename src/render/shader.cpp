#include "shader.h"

#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

namespace mobb::render {

namespace {

GLuint compile(GLenum kind, const char* name) {
    const char* text = shader_source(name);
    if (!text) throw std::runtime_error(std::string("shader ") + name + ": not embedded");
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        glDeleteShader(shader);
        throw std::runtime_error(std::string("shader ") + name + ": " + log);
    }
    return shader;
}

}  // namespace

Program::Program(const char* vertex, const char* fragment) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment);
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(id_, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("program ") + vertex + " + " + fragment + ": " + log);
    }
}

Program::~Program() { glDeleteProgram(id_); }

void Program::set(const char* name, const glm::mat4& m) const {
    glUniformMatrix4fv(glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(m));
}
void Program::set(const char* name, const glm::vec4& v) const {
    glUniform4fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, float v) const { glUniform1f(glGetUniformLocation(id_, name), v); }
void Program::set(const char* name, int v) const { glUniform1i(glGetUniformLocation(id_, name), v); }
void Program::set(const char* name, const glm::vec3* v, int count) const {
    glUniform3fv(glGetUniformLocation(id_, name), count, glm::value_ptr(v[0]));
}

}  // namespace mobb::render
