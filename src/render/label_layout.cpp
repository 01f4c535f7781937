#include "label_layout.h"

#include <algorithm>

namespace mobb::render {

bool TextBox::near(const TextBox& o, float gap) const {
    return x0 < o.x1 + gap && o.x0 < x1 + gap && y0 < o.y1 + gap && o.y0 < y1 + gap;
}

bool TextBox::inside(float width, float height) const { return x0 >= 0 && y0 >= 0 && x1 <= width && y1 <= height; }

namespace {

/// Labels keep twice the gap between them from the viewport's edges.
float edge_margin(float gap) { return 2.0f * gap; }

/// The box moved the least distance that brings it within the viewport's margin (as far as it fits).
TextBox into_view(const TextBox& b, float width, float height, float gap) {
    const float m = edge_margin(gap);
    const float dx = b.x0 < m ? m - b.x0 : b.x1 > width - m ? width - m - b.x1 : 0.0f;
    const float dy = b.y0 < m ? m - b.y0 : b.y1 > height - m ? height - m - b.y1 : 0.0f;
    return b.moved(dx, dy);
}

/// The box lies within the viewport's margin and clear of every kept box and reserved one.
bool free_at(const TextBox& b, const std::vector<TextBox>& kept, const std::vector<TextBox>& reserved, float width,
             float height, float gap) {
    const float m = edge_margin(gap);
    if (!b.moved(-m, -m).inside(width - 2 * m, height - 2 * m)) return false;
    const auto near = [&](const TextBox& o) { return b.near(o, gap); };
    return std::none_of(kept.begin(), kept.end(), near) && std::none_of(reserved.begin(), reserved.end(), near);
}

/// Where a title goes: into the viewport, then the nearest free place a whole line up or down (a few tried).
bool place_title(TextBox& b, const std::vector<TextBox>& kept, const std::vector<TextBox>& reserved, float width,
                 float height, float gap) {
    const TextBox start = into_view(b, width, height, gap);
    const float line = start.y1 - start.y0 + gap;
    for (int k = 0; k <= 6; ++k) {
        const TextBox tried = start.moved(0, line * float(k % 2 == 1 ? (k + 1) / 2 : -(k / 2)));
        if (free_at(tried, kept, reserved, width, height, gap)) {
            b = tried;
            return true;
        }
    }
    return false;
}

}  // namespace

std::vector<bool> lay_out_labels(std::vector<LabelSpot>& labels, const std::vector<TextBox>& reserved, float width,
                                 float height, float gap) {
    std::vector<bool> drawn(labels.size(), false);
    std::vector<TextBox> kept;
    const auto keep = [&](std::size_t k, const TextBox& box) {
        labels[k].box = box;
        kept.push_back(box);
        drawn[k] = true;
    };
    // Overlays are the colour bars' own text, beside their bars by construction.
    for (std::size_t k = 0; k < labels.size(); ++k)
        if (labels[k].role == LabelRole::Overlay && free_at(labels[k].box, kept, {}, width, height, gap))
            keep(k, labels[k].box);
    for (std::size_t k = 0; k < labels.size(); ++k) {
        TextBox box = labels[k].box;
        if (labels[k].role == LabelRole::Title && labels[k].anchor_inside &&
            place_title(box, kept, reserved, width, height, gap))
            keep(k, box);
    }
    // Ticks on their own side first; then those left over across their axis, where there is room.
    for (std::size_t k = 0; k < labels.size(); ++k)
        if (labels[k].role == LabelRole::Tick && free_at(labels[k].box, kept, reserved, width, height, gap))
            keep(k, labels[k].box);
    for (std::size_t k = 0; k < labels.size(); ++k) {
        const std::optional<TextBox>& other = labels[k].other_side;
        if (labels[k].role == LabelRole::Tick && !drawn[k] && other &&
            free_at(*other, kept, reserved, width, height, gap))
            keep(k, *other);
    }
    return drawn;
}

}  // namespace mobb::render
