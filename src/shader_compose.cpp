// The GLSL composer: include resolution with cycle detection, define injection, #line markers.
#include <rrc/shader.hpp>

#include <algorithm>
#include <regex>
#include <sstream>

namespace rrc {

ShaderLibrary::ShaderLibrary() { add(librarySnippets()); }

void ShaderLibrary::add(std::span<const EmbeddedFile> files) {
    files_.insert(files_.end(), files.begin(), files.end());
}

void ShaderLibrary::add(std::string name, std::string text) {
    // std::list keeps the strings where they are, so the views in files_ stay valid.
    auto& [n, t] = owned_.emplace_back(std::move(name), std::move(text));
    files_.push_back({n, t});
}

std::optional<std::string_view> ShaderLibrary::find(std::string_view name) const {
    // Later additions win, so an application can override a library snippet.
    for (auto it = files_.rbegin(); it != files_.rend(); ++it)
        if (it->name == name) return it->text;
    return std::nullopt;
}

namespace {

std::string_view trimLeft(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

// "a/b/../c.glsl" -> "a/c.glsl"; returns empty on escaping above the root.
std::string normalizePath(std::string_view path) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in{std::string(path)};
    while (std::getline(in, part, '/')) {
        if (part.empty() || part == ".") continue;
        if (part == "..") {
            if (parts.empty()) return {};
            parts.pop_back();
        } else {
            parts.push_back(part);
        }
    }
    std::string out;
    for (auto& p : parts) out += (out.empty() ? "" : "/") + p;
    return out;
}

bool isConditional(std::string_view directive) {
    for (std::string_view d : {"#if", "#else", "#elif", "#endif"})
        if (directive.starts_with(d)) return true;
    return false;
}

std::string directoryOf(std::string_view file) {
    const auto slash = file.rfind('/');
    return slash == std::string_view::npos ? std::string() : std::string(file.substr(0, slash + 1));
}

class Composer {
public:
    Composer(const ShaderLibrary& library) : library_(library) {}

    Result<ComposedShader> run(std::string_view file, std::span<const Define> defines) {
        auto text = library_.find(file);
        if (!text) return fail(LogId::ShaderFileNotFound, "shader file not found: " + std::string(file));
        std::string_view body = *text;
        int firstLine = 1;
        const auto versionPos = body.find("#version");
        const bool hasVersion = versionPos != std::string_view::npos &&
                                trimLeft(body.substr(0, versionPos)).empty();
        if (hasVersion) {
            const auto eol = body.find('\n', versionPos);
            out_ << body.substr(0, eol == std::string_view::npos ? body.size() : eol) << '\n';
            body = eol == std::string_view::npos ? std::string_view() : body.substr(eol + 1);
            firstLine = 2;
        } else {
            out_ << "#version 450 core\n";
        }
        for (const auto& d : defines) out_ << "#define " << d.name << ' ' << d.value << '\n';
        if (auto r = emit(std::string(file), body, firstLine); !r) return r.error();
        return ComposedShader{out_.str(), files_};
    }

private:
    Result<void> emit(const std::string& name, std::string_view text, int firstLine) {
        const int index = static_cast<int>(files_.size());
        files_.push_back(name);
        done_.push_back(name);
        stack_.push_back(name);
        out_ << "#line " << firstLine << ' ' << index << '\n';
        int line = firstLine;
        size_t pos = 0;
        while (pos <= text.size()) {
            auto eol = text.find('\n', pos);
            if (eol == std::string_view::npos) eol = text.size();
            const std::string_view row = text.substr(pos, eol - pos);
            pos = eol + 1;
            const auto directive = trimLeft(row);
            if (directive.starts_with("#include")) {
                if (auto r = include(name, directive, line); !r) return r;
                out_ << "#line " << line + 1 << ' ' << index << '\n';
            } else if (directive.starts_with("#version")) {
                return fail(LogId::ShaderSyntax, name + ":" + std::to_string(line) +
                                                     ": #version is only allowed on the first line of a stage file");
            } else if (pos <= text.size() || !row.empty()) {
                out_ << row << '\n';
                // An include inside a conditional block that the compiler skips also skips the
                // #line that restored this file's numbering: restore it after every conditional.
                if (isConditional(directive)) out_ << "#line " << line + 1 << ' ' << index << '\n';
            }
            ++line;
        }
        stack_.pop_back();
        return {};
    }

    Result<void> include(const std::string& from, std::string_view directive, int line) {
        const std::string where = from + ":" + std::to_string(line);
        auto arg = trimLeft(directive.substr(8));
        const char open = arg.empty() ? '\0' : arg.front();
        const char close = open == '<' ? '>' : '"';
        const auto end = arg.find(close, 1);
        if ((open != '<' && open != '"') || end == std::string_view::npos)
            return fail(LogId::ShaderSyntax, where + ": malformed #include (expected <rrc/...> or \"file\")");
        const std::string requested(arg.substr(1, end - 1));
        // <...> names a file by its full name; "..." is relative to the including file.
        std::string target = open == '<' ? normalizePath(requested) : normalizePath(directoryOf(from) + requested);
        auto text = target.empty() ? std::nullopt : library_.find(target);
        if (!text)
            return fail(LogId::ShaderIncludeNotFound, where + ": included file not found: " + requested);
        if (std::find(stack_.begin(), stack_.end(), target) != stack_.end()) {
            std::string chain;
            for (auto& s : stack_) chain += s + " -> ";
            return fail(LogId::ShaderIncludeCycle, where + ": include cycle: " + chain + target);
        }
        if (std::find(done_.begin(), done_.end(), target) != done_.end()) return {};  // once only
        return emit(target, *text, 1);
    }

    const ShaderLibrary& library_;
    std::ostringstream out_;
    std::vector<std::string> files_, done_, stack_;
};

} // namespace

Result<ComposedShader> composeShader(std::string_view file, std::span<const Define> defines,
                                     const ShaderLibrary& library) {
    return Composer(library).run(file, defines);
}

std::string mapShaderLog(std::string_view log, std::span<const std::string> files) {
    // Mesa: "0:12(5): error: ..."   NVIDIA: "0(12) : error C0000: ..."
    static const std::regex mesa(R"((^|\n)(\d+):(\d+)\((\d+)\))");
    static const std::regex nvidia(R"((^|\n)(\d+)\((\d+)\))");
    std::string text(log);
    std::string out;
    auto rewrite = [&](const std::regex& re, bool hasColumn) {
        out.clear();
        auto begin = text.cbegin();
        std::smatch m;
        while (std::regex_search(begin, text.cend(), m, re)) {
            out.append(begin, m[0].first);
            const size_t index = std::stoul(m[2].str());
            const std::string name = index < files.size() ? files[index] : m[2].str();
            out += m[1].str() + name + ":" + m[3].str();
            if (hasColumn) out += ":" + m[4].str();
            begin = m[0].second;
        }
        out.append(begin, text.cend());
        text = out;
    };
    rewrite(mesa, true);
    rewrite(nvidia, false);
    return text;
}

} // namespace rrc
