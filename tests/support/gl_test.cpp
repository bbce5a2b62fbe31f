// The shared context, the GL test fixture and main() for GL test binaries.
#include "gl_test.hpp"

#include <cstdlib>
#include <memory>
#include <optional>

namespace rrc::test {
namespace {

std::optional<Context> context;

class ContextEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        // Mesa must report errors: MESA_NO_ERROR would silence every GL error and debug message.
        ::unsetenv("MESA_NO_ERROR");
        const char* env = std::getenv("RRC_GL_BACKEND");
        auto backend = parseBackend(env && *env ? env : "egl");
        ASSERT_TRUE(backend.ok());
        auto created = Context::create({.backend = backend.value(), .width = 64, .height = 64, .visible = false});
        ASSERT_TRUE(created.ok()) << created.error().message;
        context.emplace(std::move(created).value());
        std::printf("GL test context: %s on %s\n", std::string(backendName(context->backend())).c_str(),
                    context->renderer().c_str());
    }
    void TearDown() override { context.reset(); }
};

} // namespace

Context& glContext() { return *context; }

void GLTest::SetUp() {
    ASSERT_TRUE(context.has_value()) << "no GL context";
    checkGLErrors("before test");
    resetDebugCounters();
    liveObjectsAtStart_ = liveGlObjects();
}

void GLTest::TearDown() {
    checkGLErrors("end of test");
    const auto counters = debugCounters();
    EXPECT_EQ(counters.glErrors, 0) << "GL errors during the test (see log)";
    EXPECT_EQ(counters.debugErrors, 0) << "KHR_debug error messages during the test (see log)";
}

GLTest::~GLTest() {
    library = ShaderLibrary();
    EXPECT_EQ(liveGlObjects(), liveObjectsAtStart_) << "GL objects leaked by the test";
}

Program GLTest::program(const std::string& vertexName, const std::string& vertex,
                        const std::string& fragmentName, const std::string& fragment,
                        std::vector<Define> defines) {
    library.add(vertexName, vertex);
    library.add(fragmentName, fragment);
    auto built = buildProgram({.vertex = vertexName, .fragment = fragmentName, .defines = std::move(defines)}, library);
    EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
    return built.ok() ? std::move(built).value() : Program();
}

} // namespace rrc::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    // gtest takes ownership of the environment.
    ::testing::AddGlobalTestEnvironment(std::make_unique<rrc::test::ContextEnvironment>().release());
    return RUN_ALL_TESTS();
}
