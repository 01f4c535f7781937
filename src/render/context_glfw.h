// A desktop window with an OpenGL 3.3 core context (GLFW), GL loaded through glad.
#pragma once
#include <glm/vec2.hpp>

struct GLFWwindow;

namespace mobb::render {

/// Whether a window system looks reachable (DISPLAY or WAYLAND_DISPLAY set).
bool display_available();

class GlfwWindow {
public:
    /// Opens the window and makes its context current. Throws std::runtime_error.
    GlfwWindow(const char* title, int width, int height);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool should_close() const;
    void swap() const;
    glm::ivec2 framebuffer_size() const;
    glm::ivec2 window_size() const;

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace mobb::render
