// The space-time renderer: one code path for the window and for headless images. Draws a Frame
// into the bound framebuffer.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "camera.h"
#include "disk_layer.h"
#include "draw_counts.h"
#include "frame.h"
#include "label_layout.h"
#include "space.h"

namespace mobb::render {

/// Space-time bounds of every visible clip's disks (world positions, global times).
Bounds scene_bounds(const Frame& frame);

/// GL-world corners of space-time bounds at a time scale (for Camera::frame).
void gl_bounds(const Bounds& bounds, double time_scale, glm::vec3& lo, glm::vec3& hi);

/// Scenes of more disks than this are drawn with one sample per pixel whatever Frame::multisample says.
constexpr std::size_t kMultisampleUpTo = 100000;

/// Whether the frame is drawn multisampled: asked for, and at most kMultisampleUpTo disks. A headless
/// target is made with 4 samples or 1 by it (one sample: a quarter of the depth and colour writes).
bool multisampled(const Frame& frame);

/// Where in the framebuffer the scene is drawn, GL pixels from the bottom-left corner (the window's free
/// rectangle between its panel columns). Its labels lie wholly inside it (label_layout.h).
struct Viewport {
    int x = 0, y = 0, width = 0, height = 0;
};

class Renderer {
public:
    Renderer();  ///< needs a current GL 3.3 core context
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void draw(const Frame& frame, const Camera& camera, int width, int height);  ///< the whole framebuffer
    /// Clears the whole framebuffer, then draws in `viewport` (its aspect, its labels and colour bars).
    void draw(const Frame& frame, const Camera& camera, const Viewport& viewport);
    /// What the last draw drew of the disk stacks (instances and level of detail).
    const DiskStats& disk_stats() const;
    /// Draw calls and vertices of the last draw (panels drawn after it not included).
    const DrawCounts& draw_counts() const { return counts_; }
    /// The labels the last draw drew (text, box in the viewport's pixels from its top-left corner).
    const std::vector<DrawnLabel>& labels() const;

private:
    struct Layers;
    std::unique_ptr<Layers> layers_;
    std::uint64_t revision_ = ~std::uint64_t(0);
    Bounds bounds_;
    DrawCounts counts_;
};

}  // namespace mobb::render
