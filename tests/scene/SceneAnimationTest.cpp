// Animation sampling against values worked out by hand: LINEAR (lerp, slerp on the shorter arc),
// STEP, CUBICSPLINE (a Hermite spline that must reproduce a straight line), clamping and looping.
#include "animation.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <filesystem>

namespace rrc::test {
namespace {

using namespace rrc::scene;

constexpr double kEps = 1e-9;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// Translation keys (0,0,0) at 0 s, (2,0,0) at 1 s, (2,4,0) at 3 s on node 1 of two nodes.
Animation translationClip(Interpolation interpolation = Interpolation::Linear) {
    Animation clip;
    clip.samplers.push_back({.times = {0, 1, 3}, .values = {{0, 0, 0, 0}, {2, 0, 0, 0}, {2, 4, 0, 0}}, .interpolation = interpolation});
    clip.channels.push_back({.sampler = 0, .node = 1, .path = AnimationPath::Translation});
    clip.start = 0;
    clip.end = 3;
    return clip;
}

glm::dvec3 translationAt(const Animation& clip, double time, bool loop) {
    std::vector<Transform> locals(2);
    sampleAnimation(clip, time, loop, locals);
    return locals[1].translation;
}

TEST(SceneAnimation, LinearTranslationBetweenKeys) {
    const Animation clip = translationClip();
    expectNear(translationAt(clip, 0.0, false), {0, 0, 0});
    expectNear(translationAt(clip, 0.5, false), {1, 0, 0});
    expectNear(translationAt(clip, 1.0, false), {2, 0, 0});
    expectNear(translationAt(clip, 2.0, false), {2, 2, 0});
    expectNear(translationAt(clip, 2.5, false), {2, 3, 0});
}

TEST(SceneAnimation, ClampsOutsideTheClip) {
    const Animation clip = translationClip();
    expectNear(translationAt(clip, -1.0, false), {0, 0, 0});
    expectNear(translationAt(clip, 10.0, false), {2, 4, 0});
}

TEST(SceneAnimation, Loops) {
    const Animation clip = translationClip();
    expectNear(translationAt(clip, 3.5, true), {1, 0, 0});       // 3.5 wraps to 0.5
    expectNear(translationAt(clip, 3.0 * 7 + 2.0, true), {2, 2, 0});
    expectNear(translationAt(clip, -0.5, true), {2, 3, 0});      // -0.5 wraps to 2.5
    EXPECT_DOUBLE_EQ(clipTime(clip, 6.0, true), 0.0);
    EXPECT_DOUBLE_EQ(clipTime(clip, std::nan(""), true), 0.0);
}

TEST(SceneAnimation, StepHoldsTheKeyValue) {
    const Animation clip = translationClip(Interpolation::Step);
    expectNear(translationAt(clip, 0.99, false), {0, 0, 0});
    expectNear(translationAt(clip, 1.0, false), {2, 0, 0});
    expectNear(translationAt(clip, 2.9, false), {2, 0, 0});
}

// 0 to 90 degrees about z over one second; halfway must be 45 degrees, whichever sign the file
// gave the second quaternion (q and -q are the same rotation: slerp must take the shorter arc).
TEST(SceneAnimation, LinearRotationSlerpsOnTheShorterArc) {
    const glm::dquat q90 = glm::angleAxis(glm::half_pi<double>(), glm::dvec3(0, 0, 1));
    for (double sign : {1.0, -1.0}) {
        Animation clip;
        clip.samplers.push_back({.times = {0, 1}, .values = {{0, 0, 0, 1}, sign * glm::dvec4(q90.x, q90.y, q90.z, q90.w)}});
        clip.channels.push_back({.sampler = 0, .node = 0, .path = AnimationPath::Rotation});
        clip.end = 1;
        std::vector<Transform> locals(1);
        for (double t : {0.25, 0.5, 0.75}) {
            sampleAnimation(clip, t, false, locals);
            const double angle = t * glm::half_pi<double>();
            EXPECT_NEAR(glm::length(locals[0].rotation), 1.0, kEps);
            expectNear(locals[0].rotation * glm::dvec3(1, 0, 0), {std::cos(angle), std::sin(angle), 0});
        }
    }
}

// Keys 0 at t=0 and 2 at t=2 with all tangents 1 per second: the Hermite spline is v(t) = t.
TEST(SceneAnimation, CubicSplineReproducesALine) {
    Animation clip;
    const glm::dvec4 one(1, 1, 1, 0), zero(0.0), two(2, 2, 2, 0);
    clip.samplers.push_back({.times = {0, 2}, .values = {one, zero, one, one, two, one}, .interpolation = Interpolation::CubicSpline});
    clip.channels.push_back({.sampler = 0, .node = 0, .path = AnimationPath::Scale});
    clip.end = 2;
    std::vector<Transform> locals(1);
    for (double t : {0.0, 0.3, 0.5, 1.0, 1.7, 2.0}) {
        sampleAnimation(clip, t, false, locals);
        expectNear(locals[0].scale, glm::dvec3(t));
    }
}

TEST(SceneAnimation, ChannelsTouchOnlyTheirComponent) {
    const Animation clip = translationClip();
    std::vector<Transform> locals(2);
    locals[1].scale = glm::dvec3(3.0);
    locals[0].translation = glm::dvec3(7.0);
    sampleAnimation(clip, 0.5, false, locals);
    expectNear(locals[1].scale, glm::dvec3(3.0));
    expectNear(locals[0].translation, glm::dvec3(7.0));
}

TEST(SceneAnimation, CharacterRunCycleIsFiniteAndUnit) {
    auto loaded = loadScene(std::string(RRC_SCENE_ASSETS) + "/character.glb");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const Scene& s = loaded.value();
    const Animation& run = s.animations[0];
    std::vector<Transform> locals;
    for (const Node& n : s.nodes) locals.push_back(n.local);
    for (int i = 0; i <= 100; ++i) {
        sampleAnimation(run, run.start + (run.end - run.start) * i / 37.0, true, locals);
        for (const Transform& t : locals) {
            EXPECT_NEAR(glm::length(t.rotation), 1.0, 1e-9);
            EXPECT_TRUE(std::isfinite(t.translation.x + t.translation.y + t.translation.z));
        }
    }
}

} // namespace
} // namespace rrc::test
