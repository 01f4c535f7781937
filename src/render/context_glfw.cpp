#include "context_glfw.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <GLFW/glfw3.h>
#include "gl.h"

namespace mobb::render {

bool display_available() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

GlfwWindow::GlfwWindow(const char* title, int width, int height) {
    if (!glfwInit()) throw std::runtime_error("GLFW: cannot initialise (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("GLFW: cannot open an OpenGL 3.3 core window");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw std::runtime_error("GLFW: cannot load OpenGL functions");
    }
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::swap() const { glfwSwapBuffers(window_); }

glm::ivec2 GlfwWindow::framebuffer_size() const {
    glm::ivec2 s;
    glfwGetFramebufferSize(window_, &s.x, &s.y);
    return s;
}

glm::ivec2 GlfwWindow::window_size() const {
    glm::ivec2 s;
    glfwGetWindowSize(window_, &s.x, &s.y);
    return s;
}

}  // namespace mobb::render
