// Foot contacts found in a foot's track (hysteresis, short touches dropped, close contacts merged) and the
// two-joint IK on hand-made legs: reachable, out of reach, straight, folded (foot_contact.h).
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "mobb/crowd/motion/foot_contact.h"

namespace mobb::crowd {
namespace {

constexpr double kDt = 1.0 / 30.0;

// A hand-made leg standing at the origin: hip 0.9 m up, thigh 0.45 m and shin 0.45 m, knee bent forward (+x).
const glm::dvec3 kHip(0, 0, 0.9), kKnee(0.1, 0, 0.9 - std::sqrt(0.45 * 0.45 - 0.01));
const glm::dvec3 kAnkle(0, 0, kKnee.z - std::sqrt(0.45 * 0.45 - 0.01));
const glm::dvec3 kForward(1, 0, 0);

TEST(TwoJointIk, ReachesATargetInReachKeepingLengthsAndTheKneesSide) {
    const glm::dvec3 target(0.15, 0.05, 0.2);
    const LegSolve s = two_joint_ik(kHip, kKnee, kAnkle, target, kForward);
    EXPECT_LT(glm::length(s.ankle - target), 1e-12);
    EXPECT_EQ(s.residual, 0.0);
    EXPECT_NEAR(glm::length(s.knee - kHip), 0.45, 1e-12);
    EXPECT_NEAR(glm::length(s.ankle - s.knee), 0.45, 1e-12);
    // The knee stays in front of the hip-target line, as the pose had it.
    const glm::dvec3 u = glm::normalize(target - kHip);
    const glm::dvec3 off = (s.knee - kHip) - glm::dot(s.knee - kHip, u) * u;
    EXPECT_GT(off.x, 0.05);
}

TEST(TwoJointIk, AnUnreachableTargetGetsTheStraightLegAndTheShortfall) {
    const glm::dvec3 target(0.3, 0.0, -0.2);  // 1.14 m from the hip; the leg spans 0.9 m
    const LegSolve s = two_joint_ik(kHip, kKnee, kAnkle, target, kForward);
    const double d = glm::length(target - kHip);
    EXPECT_NEAR(s.residual, d - 0.9, 1e-12);
    EXPECT_NEAR(glm::length(s.ankle - target), d - 0.9, 1e-12);
    EXPECT_NEAR(glm::length(s.ankle - kHip), 0.9, 1e-12);
    // Straight: the knee halfway along the hip-ankle line.
    EXPECT_LT(glm::length(s.knee - 0.5 * (kHip + s.ankle)), 1e-12);
}

TEST(TwoJointIk, AStraightLegBendsTowardsTheFoot) {
    const glm::dvec3 knee(0, 0, 0.45), ankle(0, 0, 0);  // no pole in the pose
    const glm::dvec3 target(0, 0, 0.1);                 // nearer: the knee must bend
    const LegSolve s = two_joint_ik(kHip, knee, ankle, target, kForward);
    EXPECT_LT(glm::length(s.ankle - target), 1e-12);
    EXPECT_NEAR(glm::length(s.knee - kHip), 0.45, 1e-12);
    EXPECT_NEAR(glm::length(s.ankle - s.knee), 0.45, 1e-12);
    EXPECT_GT(s.knee.x, 0.2);  // forward, the foot's way
    EXPECT_NEAR(s.knee.y, 0.0, 1e-12);
    // Aimed at exactly where it stands, a straight leg stays straight.
    const LegSolve same = two_joint_ik(kHip, knee, ankle, ankle, kForward);
    EXPECT_LT(glm::length(same.knee - knee), 1e-12);
    EXPECT_EQ(same.residual, 0.0);
}

TEST(TwoJointIk, ATargetTooNearFoldsTheLeg) {
    const glm::dvec3 knee(0.1, 0, 0.5), ankle(0, 0, 0.2);  // thigh 0.41 m, shin 0.32 m
    const double thigh = glm::length(knee - kHip), shin = glm::length(ankle - knee);
    const glm::dvec3 target = kHip + glm::dvec3(0, 0, -0.01);
    const LegSolve s = two_joint_ik(kHip, knee, ankle, target, kForward);
    EXPECT_NEAR(glm::length(s.ankle - kHip), std::abs(thigh - shin), 1e-12);
    EXPECT_NEAR(s.residual, std::abs(std::abs(thigh - shin) - 0.01), 1e-12);
}

// One foot's heel and toe over 60 samples: down for samples [10, 30), a 2-sample lift, down [32, 45),
// a touch in passing at 52; elsewhere 0.2 m up and swinging at 1.5 m/s.
std::array<std::vector<glm::dvec3>, 2> walk_foot(double hover) {
    std::vector<glm::dvec3> p;
    double x = 0;
    for (int i = 0; i < 60; ++i) {
        const bool down = (i >= 10 && i < 30) || (i >= 32 && i < 45) || i == 52;
        if (!down) x += 1.5 * kDt;
        p.push_back({x, 0.0, down ? hover : 0.2});
    }
    return {p, p};
}

TEST(FootContacts, ContactsHaveAStartAndAnEndAndShortTouchesAreDropped) {
    const auto foot = walk_foot(0.0);
    const auto feet = detect_contacts({foot[0], foot[1]}, {foot[0], foot[1]}, kDt);
    GraphClip clip;
    clip.first = 0;
    clip.exit = 60;
    const std::vector<ContactSpan> spans = clip_contacts(feet, clip);
    // The lift is shorter than merge_gap: one contact; the touch in passing is too fast to count.
    ASSERT_EQ(spans.size(), 2u);  // left and right, the same track
    for (const ContactSpan& s : spans) {
        EXPECT_GE(s.first, 10);
        EXPECT_LE(s.first, 11);  // the speed's central difference sees the landing one sample late at most
        EXPECT_GE(s.last, 43);   // and the take-off one sample early
        EXPECT_LE(s.last, 44);
    }
    EXPECT_EQ(feet[0].plant[20], Plant::Heel);
    EXPECT_EQ(feet[0].plant[5], Plant::Free);
    EXPECT_EQ(feet[0].plant[52], Plant::Free);
    EXPECT_EQ(feet[0].run_begin[20], spans[0].first);
    // A clip cut inside the contact holds its part of it.
    clip.first = 20;
    clip.exit = 40;
    const auto cut = clip_contacts(feet, clip);
    ASSERT_EQ(cut.size(), 2u);
    EXPECT_EQ(cut[0].first, 20);
    EXPECT_EQ(cut[0].last, 39);
}

TEST(FootContacts, HysteresisKeepsAFootHoveringBetweenTheThresholdsDown) {
    // Down at 0 cm, then hovering between height_on and height_off and still: still down.
    const double hover = (ContactRule{}.height_on + ContactRule{}.height_off) / 2;
    std::vector<glm::dvec3> p(40, glm::dvec3(0.0, 0.0, 0.2));
    for (int i = 5; i < 35; ++i) p[std::size_t(i)].z = i < 15 ? 0.0 : hover;
    for (int i = 0; i < 5; ++i) p[std::size_t(i)].x = -0.1 * (5 - i);
    const auto feet = detect_contacts({p, p}, {p, p}, kDt);
    for (int i = 6; i < 35; ++i) EXPECT_NE(feet[0].plant[std::size_t(i)], Plant::Free) << i;
    // Coming down to the same height after a lift does not count: above height_on.
    std::vector<glm::dvec3> q(40, glm::dvec3(0.0, 0.0, hover));
    for (int i = 0; i < 10; ++i) q[std::size_t(i)].z = i < 3 ? 0.0 : 0.2;  // on the ground, then lifted
    const auto hovering = detect_contacts({q, q}, {q, q}, kDt);
    EXPECT_EQ(hovering[0].plant[20], Plant::Free);
}

TEST(FootContacts, TheToeAloneIsThePlantedPointWhenTheHeelIsUp) {
    const auto foot = walk_foot(0.0);
    std::vector<glm::dvec3> heel = foot[0];
    for (int i = 25; i < 30; ++i) heel[std::size_t(i)].z = 0.12;  // heel off before the lift
    const auto feet = detect_contacts({heel, heel}, {foot[0], foot[0]}, kDt);
    EXPECT_EQ(feet[0].plant[20], Plant::Heel);
    EXPECT_EQ(feet[0].plant[27], Plant::Toe);
    EXPECT_EQ(feet[0].run_begin[27], 25);
}

}  // namespace
}  // namespace mobb::crowd
