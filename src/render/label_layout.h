// Where the 3D view's labels go: none overlaps another, none is cut by the viewport's edge (panels stand
// beside it, and a cut label reads as if it ran on under them) and none covers a colour bar. The one home of
// that rule; plain data, no GL, so tests can check it alone and check what the renderer reports it drew.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mobb::render {

/// A rectangle in pixels from the viewport's top-left corner, y down: [x0, x1) x [y0, y1).
struct TextBox {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    /// The two come closer than `gap` pixels; with a gap of 0, they share some area.
    bool near(const TextBox& other, float gap) const;
    /// Lies wholly within a viewport `width` x `height` pixels.
    bool inside(float width, float height) const;
    TextBox moved(float dx, float dy) const { return {x0 + dx, y0 + dy, x1 + dx, y1 + dy}; }
};

/// What a label is to the layout, also the order in which it is placed. An overlay (a colour bar's text)
/// stays where its layer put it; a title (the time axis's, the cursor's time) is left out when the point it
/// labels lies outside the viewport, else moved into the viewport when its edge cuts it, and by whole lines up
/// or down to a free place when a label placed before it is there; a tick label goes to its other side (when
/// it has one) if the edge cuts it or a label placed before it is near, and is left out when neither side is
/// free.
enum class LabelRole : std::uint8_t { Overlay, Title, Tick };

struct LabelSpot {
    TextBox box;  ///< where the label's anchor puts it (moved by the layout)
    LabelRole role = LabelRole::Tick;
    bool anchor_inside = true;            ///< the point it labels lies in the viewport (read for titles)
    std::optional<TextBox> other_side{};  ///< a tick label's box across its axis (read for ticks)
};

/// Pixels between two labels at a text scale (text_scale()): one pixel of the font.
inline float label_gap(float scale) { return scale; }

/// Lays out the labels of one viewport `width` x `height`: overlays, then titles, then ticks on their own
/// side, then the ticks left over on their other side, each in the order given. Returns for each label whether it is drawn; the boxes of drawn ones are where they
/// go: `gap` apart at least, twice that from the viewport's edges and clear of the `reserved` boxes (the
/// colour bars).
std::vector<bool> lay_out_labels(std::vector<LabelSpot>& labels, const std::vector<TextBox>& reserved, float width,
                                 float height, float gap);

/// A label as drawn: its text and box, its role.
struct DrawnLabel {
    std::string text;
    TextBox box;
    LabelRole role = LabelRole::Tick;
};

}  // namespace mobb::render
