// Numbered, named diagnostics. Every failure rrc reports goes through one replaceable logger,
// so applications can route messages and tests can assert on the ids rather than on text.
#pragma once
#include <functional>
#include <string>
#include <string_view>

namespace rrc {

#define RRC_LOG_IDS(X)                                                                         \
    X(GlLoadFailed, 1)              X(GlError, 2)                 X(GlDebugMessage, 3)         \
    X(ContextCreateFailed, 10)      X(BackendUnknown, 11)                                      \
    X(ShaderFileNotFound, 20)       X(ShaderIncludeNotFound, 21)  X(ShaderIncludeCycle, 22)    \
    X(ShaderCompileFailed, 23)      X(ProgramLinkFailed, 24)      X(ShaderSyntax, 25)          \
    X(FramebufferIncomplete, 30)                                                               \
    X(ImageReadFailed, 40)          X(ImageWriteFailed, 41)       X(ImageMismatch, 42)         \
    X(CacheInvalidDesc, 50)         X(CacheInvalidObject, 51)     X(CacheBadArgument, 52)      \
    X(CacheTooLarge, 53)            X(CacheNonFinite, 54)         X(CacheWrongContext, 55)     \
    X(SceneLoadFailed, 60)          X(SceneInvalid, 61)

enum class LogId : int {
#define RRC_X(name, number) name = number,
    RRC_LOG_IDS(RRC_X)
#undef RRC_X
};

enum class LogLevel { Info, Warning, Error };

struct LogItem {
    LogId id;
    LogLevel level;
    std::string_view message;
};

std::string_view logIdName(LogId id);

using Logger = std::function<void(const LogItem&)>;

// Replaces the logger (an empty one restores the default, which prints to stderr); returns the old.
Logger setLogger(Logger logger);

void log(LogId id, LogLevel level, std::string_view message);
inline void logError(LogId id, std::string_view message) { log(id, LogLevel::Error, message); }
inline void logWarning(LogId id, std::string_view message) { log(id, LogLevel::Warning, message); }

} // namespace rrc
