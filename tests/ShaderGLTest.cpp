// Compile errors in included snippets name the snippet's file and line (through #line mapping).
#include "support/gl_test.hpp"
#include "support/log_capture.hpp"

namespace rrc::test {
namespace {

class ShaderErrors : public GLTest {};

TEST_F(ShaderErrors, ErrorInIncludedSnippetNamesSnippetFileAndLine) {
    LogCapture log;
    library.add("app/broken/helper.glsl", "float ok_value() { return 1.0; }\n\nfloat broken() { return undefined_symbol; }\n");
    library.add("app/broken/main.frag",
                "#version 450 core\n#include \"helper.glsl\"\nout vec4 c;\nvoid main() { c = vec4(broken()); }\n");
    library.add("app/broken/main.vert", "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    auto built = buildProgram({.vertex = "app/broken/main.vert", .fragment = "app/broken/main.frag"}, library);
    ASSERT_FALSE(built.ok());
    EXPECT_EQ(built.error().id, LogId::ShaderCompileFailed);
    EXPECT_NE(built.error().message.find("app/broken/helper.glsl:3"), std::string::npos) << built.error().message;
    EXPECT_TRUE(log.has(LogId::ShaderCompileFailed));
}

TEST_F(ShaderErrors, ErrorInStageFileAfterDefinesKeepsItsLine) {
    LogCapture log;
    library.add("app/e2.vert", "#version 450 core\nvoid main() {\n  gl_Position = vec4(0.0);\n  nonsense;\n}\n");
    auto built = buildProgram({.vertex = "app/e2.vert", .defines = {{"A"}, {"B", "2"}}}, library);
    ASSERT_FALSE(built.ok());
    EXPECT_NE(built.error().message.find("app/e2.vert:4"), std::string::npos) << built.error().message;
}

TEST_F(ShaderErrors, ErrorAfterASkippedIncludeKeepsItsLine) {
    LogCapture log;
    library.add("app/skip/big.glsl", "float a;\nfloat b;\nfloat c;\nfloat d;\n");
    library.add("app/skip/main.frag", "#version 450 core\n#ifdef NEVER\n#include \"big.glsl\"\n#endif\nout vec4 o;\n"
                                      "void main() { o = vec4(oops); }\n");
    auto built = buildProgram({.fragment = "app/skip/main.frag"}, library);
    ASSERT_FALSE(built.ok());
    EXPECT_NE(built.error().message.find("app/skip/main.frag:6"), std::string::npos) << built.error().message;
}

TEST_F(ShaderErrors, LinkErrorIsReported) {
    LogCapture log;
    library.add("app/l.vert", "#version 450 core\nout vec3 v_missing_in_frag;\nvoid main() { gl_Position = vec4(0.0); v_missing_in_frag = vec3(0); }\n");
    library.add("app/l.frag", "#version 450 core\nin vec4 v_other;\nout vec4 c;\nvoid main() { c = v_other; }\n");
    auto built = buildProgram({.vertex = "app/l.vert", .fragment = "app/l.frag"}, library);
    ASSERT_FALSE(built.ok());
    EXPECT_EQ(built.error().id, LogId::ProgramLinkFailed);
}

TEST_F(ShaderErrors, EveryLibrarySnippetCompilesAlone) {
    // Each snippet must compile when included on its own into the matching stage.
    for (const auto& file : librarySnippets()) {
        const std::string name(file.name);
        if (name.starts_with("rrc/internal/")) continue;   // stage files of rrc's own programs
        const bool vertex = name.ends_with(".vert");
        const std::string host = "app/host_" + std::to_string(&file - librarySnippets().data()) + (vertex ? ".vert" : ".frag");
        library.add(host, "#version 450 core\n#include <" + name + ">\nvoid main() {}\n");
        auto built = vertex ? buildProgram({.vertex = host}, library) : buildProgram({.fragment = host}, library);
        EXPECT_TRUE(built.ok()) << name << ": " << (built.ok() ? "" : built.error().message);
    }
}

} // namespace
} // namespace rrc::test
