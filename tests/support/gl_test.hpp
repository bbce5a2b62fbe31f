// GoogleTest support for GL tests: one headless context per test binary (backend from
// RRC_GL_BACKEND, default egl), and a fixture that fails a test on any GL error, KHR_debug error
// message (compiler diagnostics aside) or leaked GL object.
#pragma once
#include <rrc/context.hpp>
#include <rrc/debug.hpp>
#include <rrc/gl_object.hpp>
#include <rrc/shader.hpp>

#include <gtest/gtest.h>

#include <string>

namespace rrc::test {

// The binary's shared context (created before the first test).
Context& glContext();

class GLTest : public ::testing::Test {
protected:
    ~GLTest() override;  // checks for leaked GL objects once the derived fixture's members are gone
    void SetUp() override;
    void TearDown() override;

    // Builds a program from inline sources registered under the given names.
    Program program(const std::string& vertexName, const std::string& vertex,
                    const std::string& fragmentName, const std::string& fragment,
                    std::vector<Define> defines = {});

    ShaderLibrary library;

private:
    long liveObjectsAtStart_ = 0;
};

} // namespace rrc::test
