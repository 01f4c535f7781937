#include "frame.h"

#include <cmath>
#include <stdexcept>

#include "space.h"

namespace mobb::render {

glm::vec3 clip_color(int index) {
    static const glm::vec3 kColors[] = {{0.20f, 0.47f, 0.80f}, {0.90f, 0.45f, 0.16f}, {0.30f, 0.65f, 0.32f},
                                        {0.60f, 0.38f, 0.76f}, {0.80f, 0.30f, 0.45f}, {0.15f, 0.65f, 0.70f}};
    if (index < 6) return kColors[index];
    // Many clips (the benchmark crowd): walk the hue circle by the golden angle.
    const float h = std::fmod(float(index) * 0.618034f, 1.0f) * 6.0f;
    const float x = 1.0f - std::fabs(std::fmod(h, 2.0f) - 1.0f);
    glm::vec3 c = h < 1   ? glm::vec3(1, x, 0)
                  : h < 2 ? glm::vec3(x, 1, 0)
                  : h < 3 ? glm::vec3(0, 1, x)
                  : h < 4 ? glm::vec3(0, x, 1)
                  : h < 5 ? glm::vec3(x, 0, 1)
                          : glm::vec3(1, 0, x);
    return 0.25f + 0.6f * c;
}

glm::vec3 level_color(int level) {
    static const glm::vec3 kColors[] = {{0.75f, 0.10f, 0.10f}, {0.95f, 0.60f, 0.05f}, {0.35f, 0.65f, 0.10f},
                                        {0.05f, 0.60f, 0.70f}, {0.25f, 0.30f, 0.85f}, {0.65f, 0.20f, 0.75f},
                                        {0.45f, 0.35f, 0.25f}, {0.35f, 0.35f, 0.35f}};
    return kColors[level % 8];
}

glm::vec3 outcome_color(TraceOutcome outcome) {
    switch (outcome) {
        case TraceOutcome::NoTimeOverlap: return {0.55f, 0.55f, 0.55f};
        case TraceOutcome::Separated: return {0.10f, 0.55f, 0.95f};
        case TraceOutcome::Overlap: return {1.00f, 0.55f, 0.00f};
        case TraceOutcome::Miss: return {0.60f, 0.25f, 0.85f};
        case TraceOutcome::Hit: return {0.95f, 0.05f, 0.10f};
    }
    return {1, 1, 1};
}

namespace {

constexpr const char* kDiskColourNames[kDiskColours] = {"clip", "radius", "speed", "time", "clearance"};
constexpr const char* kBoxColourNames[kBoxColours] = {"level", "tightness", "tests"};

template <typename E, std::size_t N>
E parse_name(const std::string& name, const char* const (&names)[N], const char* what) {
    std::string valid;
    for (std::size_t k = 0; k < N; ++k) {
        if (name == names[k]) return E(k);
        valid += (k ? ", " : "") + std::string(names[k]);
    }
    throw std::invalid_argument(std::string(what) + " colouring '" + name + "': expected one of " + valid);
}

}  // namespace

const char* to_string(DiskColour c) { return kDiskColourNames[std::size_t(c)]; }
const char* to_string(BoxColour c) { return kBoxColourNames[std::size_t(c)]; }
DiskColour parse_disk_colour(const std::string& name) { return parse_name<DiskColour>(name, kDiskColourNames, "disk"); }
BoxColour parse_box_colour(const std::string& name) { return parse_name<BoxColour>(name, kBoxColourNames, "box"); }

}  // namespace mobb::render
