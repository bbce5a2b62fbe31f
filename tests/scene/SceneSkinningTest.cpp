// Skinning on the CPU against geometry worked out by hand: a two-joint chain whose second joint
// rotates by a known angle, the anchor-relative float matrices the GPU gets, and the previous
// frame's matrices that the reprojection cache reprojects with.
#include "scene_state.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rrc::test {
namespace {

using namespace rrc::scene;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-9) {
    EXPECT_NEAR(a.x, b.x, eps) << "x";
    EXPECT_NEAR(a.y, b.y, eps) << "y";
    EXPECT_NEAR(a.z, b.z, eps) << "z";
}

// Joint 0 ("root", node 1) with joint 1 ("bone", node 2) one unit along +x, under a placement
// node (node 0) at `placement`. The inverse bind matrices are those of the chain at the origin,
// as when an animated character is placed in a level by a parent node.
Scene twoJointChain(glm::dvec3 placement = glm::dvec3(0.0)) {
    Scene s;
    s.nodes.resize(3);
    s.nodes[0].name = "placement";
    s.nodes[0].local.translation = placement;
    s.nodes[0].children = {1};
    s.nodes[1].name = "root";
    s.nodes[1].children = {2};
    s.nodes[2].name = "bone";
    s.nodes[2].local.translation = {1, 0, 0};
    s.roots = {0};
    s.linkHierarchy();
    s.skins.push_back({.joints = {1, 2},
                       .inverseBind = {glm::dmat4(1.0), glm::translate(glm::dmat4(1.0), glm::dvec3(-1, 0, 0))},
                       .skeleton = 1});
    return s;
}

// Joint 1 turns from 0 to 90 degrees about +z over one second.
Animation bend() {
    const glm::dquat q = glm::angleAxis(glm::half_pi<double>(), glm::dvec3(0, 0, 1));
    Animation clip;
    clip.samplers.push_back({.times = {0, 1}, .values = {{0, 0, 0, 1}, {q.x, q.y, q.z, q.w}}});
    clip.channels.push_back({.sampler = 0, .node = 2, .path = AnimationPath::Rotation});
    clip.end = 1;
    return clip;
}

const glm::u16vec4 kJoints(0, 1, 0, 0);
const glm::dvec4 kOnBone(0, 1, 0, 0), kHalfHalf(0.5, 0.5, 0, 0);

TEST(SceneSkinning, RestPoseLeavesVerticesInPlace) {
    const Scene s = twoJointChain();
    SceneState state(s);
    expectNear(skinPoint(state.skin(0), {2, 0, 0}, kJoints, kOnBone), {2, 0, 0});
    expectNear(skinPoint(state.skin(0), {0.5, 0.3, 0}, kJoints, kHalfHalf), {0.5, 0.3, 0});
}

// Rotating joint 1 (at x = 1) by 90 degrees about z moves the bind-pose vertex (2,0,0) to (1,1,0);
// a vertex weighted half and half ends at the average of (2,0,0) and (1,1,0).
TEST(SceneSkinning, RotatedJointMovesVertexToTheExpectedPlace) {
    const Scene s = twoJointChain();
    const Animation clip = bend();
    SceneState state(s);
    state.advance(1.0, &clip, false);
    expectNear(skinPoint(state.skin(0), {2, 0, 0}, kJoints, kOnBone), {1, 1, 0});
    expectNear(skinPoint(state.skin(0), {2, 0, 0}, kJoints, kHalfHalf), {1.5, 0.5, 0});
    expectNear(skinPoint(state.skin(0), {0, 3, 0}, kJoints, glm::dvec4(1, 0, 0, 0)), {0, 3, 0});  // joint 0 did not move
    state.advance(0.5, &clip, false);  // 45 degrees
    const double h = std::sqrt(0.5);
    expectNear(skinPoint(state.skin(0), {2, 0, 0}, kJoints, kOnBone), {1 + h, h, 0});
}

TEST(SceneSkinning, PreviousFrameHoldsTheLastCurrentMatrices) {
    const Scene s = twoJointChain();
    const Animation clip = bend();
    SceneState state(s);
    EXPECT_EQ(state.previousSkin(0).world, state.skin(0).world);  // no history yet
    state.advance(0.25, &clip, false);
    const SkinPose before = state.skin(0);
    const auto worldBefore = state.world();
    state.advance(0.75, &clip, false);
    EXPECT_EQ(state.previousSkin(0).world, before.world);
    EXPECT_EQ(state.previousSkin(0).relative, before.relative);
    EXPECT_EQ(state.previousSkin(0).anchor, before.anchor);
    EXPECT_EQ(state.previousWorld(), worldBefore);
    EXPECT_NE(state.skin(0).world, before.world);
    // The previous pose skins the vertex to where it was a frame ago.
    const double a = 0.25 * glm::half_pi<double>();
    expectNear(skinPoint(state.previousSkin(0), {2, 0, 0}, kJoints, kOnBone), {1 + std::cos(a), std::sin(a), 0});
    EXPECT_EQ(state.frame(), 2u);
    state.resetHistory();
    EXPECT_EQ(state.previousSkin(0).world, state.skin(0).world);
}

// Placed far from the origin, the float joint matrices stay small (relative to the anchor) and
// skinning in float, as the shader does, plus the anchor in double lands within float precision
// of the exact answer.
TEST(SceneSkinning, AnchorRelativeMatricesKeepPrecisionFarAway) {
    const glm::dvec3 far(1.0e6, 2.0e5, -3.0e6);
    const Scene s = twoJointChain(far);
    const Animation clip = bend();
    SceneState state(s);
    state.advance(1.0, &clip, false);
    const SkinPose& pose = state.skin(0);
    expectNear(pose.anchor, far, 1e-6);
    expectNear(glm::dvec3(state.skinModel(0)[3]), far, 1e-6);
    for (const glm::mat4& m : pose.relative) EXPECT_LT(glm::length(glm::vec3(m[3])), 4.0f);
    const glm::dvec3 exact = skinPoint(pose, {2, 0, 0}, kJoints, kOnBone);
    expectNear(exact, far + glm::dvec3(1, 1, 0), 1e-6);
    const glm::vec4 gpu = pose.relative[1] * glm::vec4(2, 0, 0, 1);
    expectNear(glm::dvec3(gpu) + far, exact, 1e-5);
}

} // namespace
} // namespace rrc::test
