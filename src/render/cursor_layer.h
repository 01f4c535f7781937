// The time cursor: a horizontal plane slicing the stacks at one instant, with each clip's skeleton
// at that instant standing on it (height scaled by the user's factor).
#pragma once
#include <cstdint>
#include <vector>

#include "batch.h"
#include "frame.h"
#include "layer.h"
#include "text_layer.h"

namespace mobb::render {

/// The animation frame playing at global time t, or -1 outside the clip.
int frame_at(const ClipView& clip, double t);

class CursorLayer {
public:
    CursorLayer() : lines_(GL_LINES), plane_(GL_TRIANGLES), posed_(GL_LINES), bodies_(GL_TRIANGLES) {}
    void draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass, TextLayer& text);
    /// The posed skeletons (frame.posed), drawn last over everything: a skeleton stands inside its own
    /// disk stack (the radius covers every joint), so depth-tested it would hide in the stack above it.
    void draw_posed(const Frame& frame, const DrawContext& ctx);

private:
    void skeletons(const Frame& frame);
    /// Lines of frame f of `anim`: ground coordinates moved by m, height above `floor` on the plane.
    void joints(Batch& out, const PosedSkeleton& pose, const Frame& frame);
    /// Layers::bodies: a capsule per bone of a pose given joint by joint, lit from one direction.
    void body(Batch& out, const PosedSkeleton& pose, const Frame& frame);
    void skeleton(Batch& out, const io::Animation& anim, io::UpAxis up, int f, const Rigid2& m, double floor,
                  const Frame& frame, const glm::vec3& color);

    Batch lines_, plane_, posed_, bodies_;
    std::uint64_t revision_ = ~std::uint64_t(0);
    std::vector<double> floor_;  ///< per clip: lowest joint height over the clip (the skeleton's feet)
};

}  // namespace mobb::render
