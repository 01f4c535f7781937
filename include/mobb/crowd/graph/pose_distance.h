// Pose distance for motion graphs: point clouds of joint positions over a short window, compared after
// the best rigid 2D alignment about the vertical axis (Kovar, Gleicher and Pighin, "Motion Graphs", 2002).
#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mobb/io/load.h"

namespace mobb::crowd {

/// The joints compared and their weights: the major joints found by name (pelvis, thighs, knees,
/// feet, toes, spine, head, upper arms, forearms, hands; CMU iClone rig names "CC_Base_L_Thigh" ...),
/// plus the skeleton's root. When fewer than 6 are found, every joint with weight 1.
struct PoseJoints {
    std::vector<int> joints;
    std::vector<double> weights;
    std::vector<std::string> names;
};
PoseJoints select_joints(const io::Skeleton& skeleton);

/// One clip's poses in ground coordinates (x, y, height), metres, ready for comparison.
struct PoseTrack {
    double dt = 1.0 / 30.0;  ///< seconds between frames
    int frames = 0, joints = 0;
    std::vector<glm::dvec3> points;  ///< frame-major: points[f * joints + j]
    std::vector<double> weights;     ///< per joint
    std::vector<glm::dvec2> root;    ///< per frame: the path's root position (io::path_of)
    std::vector<double> heading;     ///< per frame: facing direction (radians, 0 = +x), see below
};

/// Builds the track of a loaded clip. Heading: the direction the body faces, perpendicular (to the
/// front) to left-minus-right of the thighs and upper arms, averaged over +-2 frames to damp the gait's
/// sway; without those joints, the direction of the root's motion over +-2 frames.
PoseTrack pose_track(const io::Clip& clip, const PoseJoints& joints);

/// Distance between frame fa of a and frame fb of b: RMS over the window's weighted points (metres)
/// after the rigid motion about the vertical axis that best maps b's window onto a's (closed form).
/// Windows of `window` frames are centred on fa / fb and shifted to fit inside each clip.
struct PoseMatch {
    double distance = 0;    ///< metres, RMS
    double theta = 0;       ///< rotation (radians) applied to b
    glm::dvec2 shift{0.0};  ///< then this translation (metres)
};
PoseMatch pose_distance(const PoseTrack& a, int fa, const PoseTrack& b, int fb, int window = 5);

/// Every pair of frames at once, same value as pose_distance (up to rounding): row-major
/// [fa * b.frames + fb], float metres. O(frames_a * frames_b * joints).
std::vector<float> distance_matrix(const PoseTrack& a, const PoseTrack& b, int window = 5);

}  // namespace mobb::crowd
