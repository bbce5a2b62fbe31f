// The GLSL composer without a GL context: includes, defines, #line markers, cycles, errors.
#include <rrc/shader.hpp>

#include "support/log_capture.hpp"

#include <gtest/gtest.h>

namespace rrc::test {
namespace {

TEST(ShaderCompose, InjectsDefinesAfterVersionAndMarksLines) {
    ShaderLibrary lib;
    lib.add("app/a.frag", "#version 450 core\nvoid main() {}\n");
    const Define defines[] = {{"RRC_BICUBIC"}, {"RRC_TAPS", "16"}};
    auto composed = composeShader("app/a.frag", defines, lib);
    ASSERT_TRUE(composed.ok());
    EXPECT_EQ(composed.value().text,
              "#version 450 core\n#define RRC_BICUBIC 1\n#define RRC_TAPS 16\n#line 2 0\nvoid main() {}\n");
    ASSERT_EQ(composed.value().files.size(), 1u);
    EXPECT_EQ(composed.value().files[0], "app/a.frag");
}

TEST(ShaderCompose, AddsVersionWhenMissing) {
    ShaderLibrary lib;
    lib.add("app/b.frag", "void main() {}");
    auto composed = composeShader("app/b.frag", {}, lib);
    ASSERT_TRUE(composed.ok());
    EXPECT_EQ(composed.value().text, "#version 450 core\n#line 1 0\nvoid main() {}\n");
}

TEST(ShaderCompose, ResolvesLibraryAndRelativeIncludesOnce) {
    ShaderLibrary lib;
    lib.add("rrc/x.glsl", "float rrc_x;\n");
    lib.add("app/common/y.glsl", "#include <rrc/x.glsl>\nfloat y;\n");
    lib.add("app/demo/main.frag",
            "#version 450 core\n#include <rrc/x.glsl>\n  #include \"../common/y.glsl\"\nvoid main() {}\n");
    auto composed = composeShader("app/demo/main.frag", {}, lib);
    ASSERT_TRUE(composed.ok());
    const std::string expected =
        "#version 450 core\n"
        "#line 2 0\n"
        "#line 1 1\nfloat rrc_x;\n"     // rrc/x.glsl, source string 1
        "#line 3 0\n"
        "#line 1 2\n"                   // app/common/y.glsl: its own include of x is skipped
        "#line 2 2\nfloat y;\n"
        "#line 4 0\nvoid main() {}\n";
    EXPECT_EQ(composed.value().text, expected);
    EXPECT_EQ(composed.value().files, (std::vector<std::string>{"app/demo/main.frag", "rrc/x.glsl", "app/common/y.glsl"}));
}

TEST(ShaderCompose, RestoresLineNumbersAfterConditionalBlocks) {
    ShaderLibrary lib;
    lib.add("app/inc.glsl", "float a;\nfloat b;\n");
    lib.add("app/c.frag", "#version 450 core\n#ifndef SKIP\n#include \"inc.glsl\"\n#endif\nvoid main() {}\n");
    auto composed = composeShader("app/c.frag", {}, lib);
    ASSERT_TRUE(composed.ok());
    EXPECT_EQ(composed.value().text,
              "#version 450 core\n#line 2 0\n#ifndef SKIP\n#line 3 0\n#line 1 1\nfloat a;\nfloat b;\n"
              "#line 4 0\n#endif\n#line 5 0\nvoid main() {}\n");
}

TEST(ShaderCompose, DetectsIncludeCycles) {
    LogCapture log;
    ShaderLibrary lib;
    lib.add("a.glsl", "#include \"b.glsl\"\n");
    lib.add("b.glsl", "#include \"c.glsl\"\n");
    lib.add("c.glsl", "#include \"a.glsl\"\n");
    auto composed = composeShader("a.glsl", {}, lib);
    ASSERT_FALSE(composed.ok());
    EXPECT_EQ(composed.error().id, LogId::ShaderIncludeCycle);
    EXPECT_NE(composed.error().message.find("a.glsl -> b.glsl -> c.glsl -> a.glsl"), std::string::npos)
        << composed.error().message;
    EXPECT_TRUE(log.has(LogId::ShaderIncludeCycle));
}

TEST(ShaderCompose, ReportsMissingIncludeWithFileAndLine) {
    LogCapture log;
    ShaderLibrary lib;
    lib.add("app/m.frag", "#version 450 core\n\n#include <rrc/nope.glsl>\n");
    auto composed = composeShader("app/m.frag", {}, lib);
    ASSERT_FALSE(composed.ok());
    EXPECT_EQ(composed.error().id, LogId::ShaderIncludeNotFound);
    EXPECT_NE(composed.error().message.find("app/m.frag:3"), std::string::npos) << composed.error().message;
}

TEST(ShaderCompose, RejectsMissingFileEscapingPathAndMalformedInclude) {
    LogCapture log;
    ShaderLibrary lib;
    lib.add("app/e.frag", "#include \"../../outside.glsl\"\n");
    lib.add("app/f.frag", "#include rrc/x.glsl\n");
    lib.add("app/g.frag", "#version 450 core\n#include \"h.glsl\"\n");
    lib.add("app/h.glsl", "#version 450 core\n");
    EXPECT_EQ(composeShader("nope.frag", {}, lib).error().id, LogId::ShaderFileNotFound);
    EXPECT_EQ(composeShader("app/e.frag", {}, lib).error().id, LogId::ShaderIncludeNotFound);
    EXPECT_EQ(composeShader("app/f.frag", {}, lib).error().id, LogId::ShaderSyntax);
    EXPECT_EQ(composeShader("app/g.frag", {}, lib).error().id, LogId::ShaderSyntax);
}

TEST(ShaderCompose, LibrarySnippetsAreEmbedded) {
    ShaderLibrary lib;
    EXPECT_FALSE(librarySnippets().empty());
    for (const auto& file : librarySnippets()) {
        EXPECT_TRUE(file.name.starts_with("rrc/")) << file.name;
        EXPECT_FALSE(file.text.empty()) << file.name;
    }
}

TEST(ShaderCompose, MapsDriverLogsToFileNames) {
    const std::vector<std::string> files{"app/main.frag", "rrc/lookup.frag"};
    EXPECT_EQ(mapShaderLog("1:12(5): error: bad\n0:3(1): warning: w", files),
              "rrc/lookup.frag:12:5: error: bad\napp/main.frag:3:1: warning: w");
    EXPECT_EQ(mapShaderLog("1(7) : error C0000: syntax error", files), "rrc/lookup.frag:7 : error C0000: syntax error");
}

} // namespace
} // namespace rrc::test
