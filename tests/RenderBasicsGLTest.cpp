// The platform works as rrc needs: float targets with exact readback, reversed-Z with
// glClipControl, occlusion queries with conditional rendering.
#include "support/draw.hpp"
#include "support/gl_test.hpp"

namespace rrc::test {
namespace {

// Draws an axis-aligned rectangle [x0,x1]x[y0,y1] in NDC at depth z with a flat colour.
const char* kRectVert = R"(#version 450 core
uniform vec4 u_rect;  // x0 y0 x1 y1
uniform float u_z;
void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(u_rect.xy, u_rect.zw, corner), u_z, 1.0);
}
)";
const char* kFlatFrag = R"(#version 450 core
uniform vec4 u_color;
out vec4 o_color;
void main() { o_color = u_color; }
)";
const char* kTriangleVert = R"(#version 450 core
void main() {
    // Lower-left half of the viewport: (-1,-1), (1,-1), (-1,1) at NDC depth 0.5.
    vec2 p = vec2(gl_VertexID == 1 ? 1.0 : -1.0, gl_VertexID == 2 ? 1.0 : -1.0);
    gl_Position = vec4(p, 0.5, 1.0);
}
)";

class RenderBasics : public GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        vao = createVertexArray();
        rect = program("t/rect.vert", kRectVert, "t/flat.frag", kFlatFrag);
    }
    void drawRect(glm::vec4 r, float z, glm::vec4 color) {
        glUseProgram(rect.id());
        glUniform4f(glGetUniformLocation(rect.id(), "u_rect"), r.x, r.y, r.z, r.w);
        glUniform1f(glGetUniformLocation(rect.id(), "u_z"), z);
        glUniform4f(glGetUniformLocation(rect.id(), "u_color"), color.r, color.g, color.b, color.a);
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    VertexArray vao;
    Program rect;
};

TEST_F(RenderBasics, TriangleIntoFloatTargetReadsBackExactly) {
    Target t = makeTarget(64, 64, GL_RGBA16F);
    Program tri = program("t/tri.vert", kTriangleVert, "t/flat.frag", kFlatFrag);
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
    glViewport(0, 0, 64, 64);
    glClearColor(0.125f, 0.25f, 0.5f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(tri.id());
    glUniform4f(glGetUniformLocation(tri.id(), "u_color"), 0.75f, 0.5f, 0.25f, 1.0f);
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    EXPECT_EQ(readPixel(t, 2, 2), glm::vec4(0.75f, 0.5f, 0.25f, 1.0f));     // inside
    EXPECT_EQ(readPixel(t, 61, 61), glm::vec4(0.125f, 0.25f, 0.5f, 1.0f));  // outside
    EXPECT_EQ(readDepth(t, 2, 2), 0.75f);    // NDC 0.5 -> window 0.75 with the default range
    EXPECT_EQ(readDepth(t, 61, 61), 1.0f);
}

TEST_F(RenderBasics, ReversedZWithClipControlKeepsTheNearerSurface) {
    Target t = makeTarget(32, 32, GL_RGBA32F);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
    glViewport(0, 0, 32, 32);
    glClearDepth(0.0);  // reversed-Z: far is 0
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    drawRect({-1, -1, 1, 1}, 0.9f, {1, 0, 0, 1});    // near (large depth) first
    drawRect({-1, -1, 0, 1}, 0.1f, {0, 1, 0, 1});    // farther, must lose
    drawRect({0, -1, 1, 1}, 0.95f, {0, 0, 1, 1});    // nearer still, must win
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    EXPECT_EQ(readPixel(t, 4, 16), glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(readPixel(t, 28, 16), glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(readDepth(t, 4, 16), 0.9f);    // ZERO_TO_ONE: window depth equals NDC z
    EXPECT_EQ(readDepth(t, 28, 16), 0.95f);
}

TEST_F(RenderBasics, OcclusionQueryDrivesConditionalRender) {
    Target t = makeTarget(32, 32, GL_RGBA16F);
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
    glViewport(0, 0, 32, 32);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    drawRect({-1, -1, 0, 1}, -0.5f, {1, 1, 1, 1});  // occluder over the left half

    Query hidden = createQuery(GL_SAMPLES_PASSED), visible = createQuery(GL_SAMPLES_PASSED);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBeginQuery(GL_SAMPLES_PASSED, hidden.id());
    drawRect({-1, -1, 0, 1}, 0.5f, {0, 0, 0, 1});   // entirely behind the occluder
    glEndQuery(GL_SAMPLES_PASSED);
    glBeginQuery(GL_SAMPLES_PASSED, visible.id());
    drawRect({0, -1, 1, 0}, 0.5f, {0, 0, 0, 1});    // the lower-right quarter: 16x16 pixels
    glEndQuery(GL_SAMPLES_PASSED);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);

    glBeginConditionalRender(hidden.id(), GL_QUERY_WAIT);
    drawRect({-1, -1, 1, 1}, 0.0f, {1, 0, 0, 1});
    glEndConditionalRender();
    glBeginConditionalRender(visible.id(), GL_QUERY_WAIT);
    drawRect({0, 0, 1, 1}, 0.0f, {0, 1, 0, 1});     // upper-right quarter
    glEndConditionalRender();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    GLuint hiddenSamples = 99, visibleSamples = 0;
    glGetQueryObjectuiv(hidden.id(), GL_QUERY_RESULT, &hiddenSamples);
    glGetQueryObjectuiv(visible.id(), GL_QUERY_RESULT, &visibleSamples);
    EXPECT_EQ(hiddenSamples, 0u);
    EXPECT_EQ(visibleSamples, 16u * 16u);
    EXPECT_EQ(readPixel(t, 4, 4), glm::vec4(1, 1, 1, 1));     // the red draw was skipped
    EXPECT_EQ(readPixel(t, 24, 24), glm::vec4(0, 1, 0, 1));   // the green draw ran
}

} // namespace
} // namespace rrc::test
