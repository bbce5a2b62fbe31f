// rrc-microbench: what the cache costs and saves for a 5-octave Perlin marble shader on a
// full-screen plane: brute-force shading, the lookup alone, one- and two-pass flows at forced
// miss fractions (clustered in 8x8 blocks or scattered), a frame where nothing moved, and a
// camera cut. Wall clock around glFinish; median and min over repeated frames after warm-up.
#include "../demos/support/timing.hpp"

#include <rrc/cache.hpp>
#include <rrc/context.hpp>
#include <rrc/projection.hpp>

#include <CLI/CLI.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <fstream>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>

namespace rrc::bench {
std::span<const EmbeddedFile> shaders();
}

namespace {

using namespace rrc;

struct Record {
    std::string name, pattern;
    double missFraction = 0;
    demo::Timing timing;
};

struct Bench {
    int width = 1024, height = 768, frames = 30, warmup = 5, octaves = 5;
    bool bilinearDepth = true, depthInPayload = false;
    float resampleSnap = CacheDesc{}.resampleSnap;
    GLenum payloadFormat = GL_RGBA8;
    std::vector<std::string> overrides;   // NAME=PATH: replace a snippet by a file (experiments)
    std::vector<std::string> extraDefines;
    bool passTiming = false;
    Resample resample = Resample::Bilinear;
    Cache cache;
    ShaderLibrary library;
    Program brute, onePass, lookup, miss, depthOnly;
    Buffer quad;
    VertexArray vao;
    glm::dmat4 model{1.0}, view{1.0}, projection{1.0};
    Framebuffer bruteTarget;
    Texture bruteColor, bruteDepth, permutation;

    Result<void> init() {
        auto c = Cache::create({.width = width, .height = height, .payloads = {{.format = payloadFormat, .resample = resample}},
                                .stats = false, .depthInPayload = depthInPayload, .bilinearDepth = bilinearDepth,
                                .resampleSnap = resampleSnap, .stencil = false});   // two-pass without prepass: no stencil
        if (!c) return c.error();
        cache = std::move(c).value();
        library.add(demo::supportShaders());
        library.add(bench::shaders());
        for (const std::string& entry : overrides) {
            const auto eq = entry.find('=');
            const std::string name = entry.substr(0, eq), path = eq == std::string::npos ? "" : entry.substr(eq + 1);
            std::ifstream in(path);
            std::stringstream text;
            text << in.rdbuf();
            if (!in) return fail(LogId::ShaderFileNotFound, "--override: cannot read " + path);
            library.add(name, text.str());   // later additions win over the embedded snippet
        }
        auto defines = cache.defines();
        defines.push_back({"DEMO_OCTAVES", std::to_string(octaves)});
        for (const std::string& d : extraDefines) {
            const auto eq = d.find('=');
            defines.push_back(eq == std::string::npos ? Define{d} : Define{d.substr(0, eq), d.substr(eq + 1)});
        }
        auto build = [&](const char* frag, std::vector<Define> extra) -> Result<Program> {
            auto d = defines;
            d.insert(d.end(), extra.begin(), extra.end());
            return buildProgram({.vertex = "shaders/scene.vert", .fragment = frag, .defines = d}, library);
        };
        for (auto [program, frag, extra] : {std::tuple{&brute, "shaders/scene.frag", std::vector<Define>{{"BRUTE"}}},
                                            std::tuple{&onePass, "shaders/scene.frag", std::vector<Define>{}},
                                            std::tuple{&lookup, "shaders/scene.frag", std::vector<Define>{{"PASS_LOOKUP"}}},
                                            std::tuple{&miss, "shaders/scene.frag", std::vector<Define>{{"PASS_MISS"}}},
                                            std::tuple{&depthOnly, "shaders/depth.frag", std::vector<Define>{}}}) {
            auto p = build(frag, extra);
            if (!p) return p.error();
            *program = std::move(p).value();
        }
        const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
        quad = createBuffer();
        glNamedBufferStorage(quad.id(), sizeof(corners), corners, 0);
        vao = createVertexArray();
        glVertexArrayVertexBuffer(vao.id(), 0, quad.id(), 0, 2 * sizeof(float));
        glEnableVertexArrayAttrib(vao.id(), 0);
        glVertexArrayAttribFormat(vao.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao.id(), 0, 0);
        permutation = demo::permutationTexture(1);
        glBindTextureUnit(5, permutation.id());
        model = glm::scale(glm::translate(glm::dmat4(1.0), {0, 0, -10}), {40, 40, 1});
        view = glm::lookAt(glm::dvec3(0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
        projection = perspectiveReversedZ(1.0, double(width) / height, 0.1);
        bruteColor = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(bruteColor.id(), 1, GL_RGBA8, width, height);
        bruteDepth = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(bruteDepth.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
        bruteTarget = createFramebuffer();
        glNamedFramebufferTexture(bruteTarget.id(), GL_COLOR_ATTACHMENT0, bruteColor.id(), 0);
        glNamedFramebufferTexture(bruteTarget.id(), GL_DEPTH_ATTACHMENT, bruteDepth.id(), 0);
        return checkFramebuffer(bruteTarget, "brute-force target");
    }

    void draw(const Program& program, float missFraction, bool clustered) {
        const ViewState state{view, projection};
        const DrawMatrices m = composeDrawMatrices(state, state, model, model);
        const GLuint p = program.id();
        glUseProgram(p);
        glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "u_mvp"), 1, GL_FALSE, &m.modelViewProj[0][0]);
        const glm::mat4 fm(model);
        if (GLint l = glGetUniformLocation(p, "u_model"); l >= 0) glProgramUniformMatrix4fv(p, l, 1, GL_FALSE, &fm[0][0]);
        if (GLint l = glGetUniformLocation(p, "u_missFraction"); l >= 0) glProgramUniform1f(p, l, missFraction);
        if (GLint l = glGetUniformLocation(p, "u_clustered"); l >= 0) glProgramUniform1ui(p, l, clustered ? 1u : 0u);
        cache.setDrawUniforms(p, m);
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }

    void bruteFrame() {
        glBindFramebuffer(GL_FRAMEBUFFER, bruteTarget.id());
        glViewport(0, 0, width, height);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        const float zero = 0.0f, black[4] = {0, 0, 0, 1};
        glClearNamedFramebufferfv(bruteTarget.id(), GL_DEPTH, 0, &zero);
        glClearNamedFramebufferfv(bruteTarget.id(), GL_COLOR, 0, black);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        draw(brute, 0, false);
        glDisable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    bool probe = true;   // FrameDesc::skipEmptyMissPass

    void cachedFrame(ControlFlow flow, float missFraction, bool clustered, bool moved, bool cut) {
        if (cut) cache.invalidate();
        glFinish();
        const auto frameStart = std::chrono::steady_clock::now();
        (void)cache.beginFrame({.view = view, .projection = projection, .forcedMisses = missFraction > 0, .objectsMoved = moved,
                                .depthPrepass = false, .skipEmptyMissPass = probe});   // one layer: no overdraw to save
        (void)cache.render(flow, [&](Pass pass) {
            if (passTiming) glFinish();
            const auto t0 = std::chrono::steady_clock::now();
            struct Report {
                Pass pass; std::chrono::steady_clock::time_point t0; bool on;
                ~Report() { if (on) { glFinish(); std::fprintf(stderr, " [%s %.2f ms]", std::string(passName(pass)).c_str(),
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()); } }
            } report{pass, t0, passTiming};
            switch (pass) {
            case Pass::DepthPrepass: case Pass::Probe: draw(depthOnly, missFraction, clustered); break;
            case Pass::Shade: draw(onePass, missFraction, clustered); break;
            case Pass::Lookup: draw(lookup, missFraction, clustered); break;
            case Pass::Miss: draw(miss, missFraction, clustered); break;
            case Pass::Resolve: break;
            }
        });
        cache.endFrame();
        if (passTiming) {
            glFinish();
            std::fprintf(stderr, " [frame %.2f ms]", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
        }
    }

    Record run(std::string name, double missFraction, std::string pattern, const std::function<void()>& frame) {
        std::fprintf(stderr, "  %-17s miss %5.1f%% %-9s", name.c_str(), missFraction * 100, pattern.c_str());
        Record r{std::move(name), std::move(pattern), missFraction, demo::timeFrames(frame, warmup, frames)};
        std::fprintf(stderr, " median %7.2f ms  min %7.2f ms\n", r.timing.median, r.timing.min);
        return r;
    }
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"rrc-microbench: cache lookup cost against full shading"};
    Bench b;
    std::string json, backendName = "auto", size = "1024x768";
    app.add_option("--json", json, "write the records as a JSON array to FILE");
    app.add_option("--backend", backendName, "auto, egl, osmesa or glfw");
    app.add_option("--size", size, "WxH")->default_val("1024x768");
    app.add_option("--frames", b.frames, "measured frames per case")->check(CLI::Range(1, 100000));
    app.add_option("--warmup", b.warmup, "unmeasured frames first")->check(CLI::Range(0, 100000));
    app.add_option("--octaves", b.octaves, "Perlin octaves of the expensive shader")->check(CLI::Range(1, 20));
    app.add_flag("!--nearest-depth", b.bilinearDepth, "fetch cached depth without bilinear filtering");
    std::map<std::string, Resample> resamples{{"nearest", Resample::Nearest}, {"bilinear", Resample::Bilinear}, {"bicubic", Resample::Bicubic}};
    app.add_option("--resample", b.resample, "payload resampling")->transform(CLI::CheckedTransformer(resamples, CLI::ignore_case));
    app.add_option("--resample-snap", b.resampleSnap, "CacheDesc::resampleSnap in texels (0: off)")->check(CLI::Range(0.0, 0.49));
    app.add_flag("--depth-in-payload", b.depthInPayload, "linear depth in payload alpha (RGBA16F payload), one fetch per lookup");
    bool quick = false;
    app.add_flag("--quick", quick, "only the cases of issue 3's targets: full shading, lookup only, static, cut, two-pass 5% clustered");
    app.add_flag("--pass-timing", b.passTiming, "print each pass's time (glFinish around every pass; slower frames)");
    app.add_option("--define", b.extraDefines, "extra shader define NAME[=VALUE] (experiments)");
    app.add_option("--override", b.overrides, "replace a shader snippet by a file: NAME=PATH (experiments)")->delimiter(',');
    CLI11_PARSE(app, argc, argv);
    if (b.depthInPayload) b.payloadFormat = GL_RGBA16F;
    if (std::sscanf(size.c_str(), "%dx%d", &b.width, &b.height) != 2 || b.width <= 0 || b.height <= 0) {
        std::fprintf(stderr, "rrc-microbench: --size must be WxH, got '%s'\n", size.c_str());
        return 1;
    }
    auto backend = parseBackend(backendName);
    if (!backend) return 1;
    auto context = Context::create({.backend = backend.value(), .width = b.width, .height = b.height, .visible = false});
    if (!context) return 1;
    if (auto r = b.init(); !r) return 1;
    std::fprintf(stderr, "rrc-microbench: %dx%d, %d-octave Perlin, %s on %s\n", b.width, b.height, b.octaves,
                 std::string(rrc::backendName(context.value().backend())).c_str(), context.value().renderer().c_str());

    std::vector<Record> records;
    records.push_back(b.run("full-shading", 1.0, "none", [&] { b.bruteFrame(); }));
    records.push_back(b.run("lookup-only", 0.0, "none", [&] { b.cachedFrame(ControlFlow::TwoPass, 0, false, true, false); }));
    records.push_back(b.run("static", 0.0, "none", [&] { b.cachedFrame(ControlFlow::TwoPass, 0, false, false, false); }));
    records.push_back(b.run("camera-cut", 1.0, "none", [&] { b.cachedFrame(ControlFlow::TwoPass, 0, false, true, true); }));
    for (ControlFlow flow : {ControlFlow::OnePass, ControlFlow::TwoPass})
        for (bool clustered : {true, false})
            for (double f : {0.0, 0.05, 0.10, 0.50, 1.0})
                if (!quick || (flow == ControlFlow::TwoPass && clustered && f == 0.05))
                    records.push_back(b.run(flow == ControlFlow::OnePass ? "one-pass" : "two-pass", f, clustered ? "clustered" : "scattered",
                                            [&] { b.cachedFrame(flow, float(f), clustered, true, false); }));
    b.probe = false;
    for (double f : {0.0, 0.05, 0.10})
        if (!quick)
            records.push_back(b.run("two-pass-no-probe", f, "clustered", [&] { b.cachedFrame(ControlFlow::TwoPass, float(f), true, true, false); }));
    b.probe = true;
    const double full = records[0].timing.median;
    std::fprintf(stderr, "relative to full shading (%.2f ms): lookup-only %.1f%%, static %.1f%%, camera cut %.1f%%\n", full,
                 100 * records[1].timing.median / full, 100 * records[2].timing.median / full, 100 * records[3].timing.median / full);
    if (!json.empty()) {
        std::ofstream out(json);
        out << "[\n";
        for (size_t i = 0; i < records.size(); ++i) {
            const Record& r = records[i];
            out << "  {\"case\": \"" << r.name << "\", \"miss_fraction\": " << r.missFraction << ", \"pattern\": \"" << r.pattern
                << "\", \"ms_median\": " << r.timing.median << ", \"ms_min\": " << r.timing.min << ", \"width\": " << b.width
                << ", \"height\": " << b.height << ", \"octaves\": " << b.octaves << "}" << (i + 1 < records.size() ? "," : "") << "\n";
        }
        out << "]\n";
        if (!out) { std::fprintf(stderr, "rrc-microbench: cannot write %s\n", json.c_str()); return 1; }
    }
    return 0;
}
