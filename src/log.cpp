// The process-wide logger and Result support.
#include <rrc/result.hpp>

#include <cstdio>
#include <mutex>

namespace rrc {
namespace {

std::mutex& loggerMutex() {
    static std::mutex m;
    return m;
}

Logger& currentLogger() {
    static Logger logger;
    return logger;
}

const char* levelName(LogLevel level) {
    switch (level) {
    case LogLevel::Info: return "info";
    case LogLevel::Warning: return "warning";
    case LogLevel::Error: return "error";
    }
    return "?";
}

} // namespace

std::string_view logIdName(LogId id) {
    switch (id) {
#define RRC_X(name, number) case LogId::name: return #name;
        RRC_LOG_IDS(RRC_X)
#undef RRC_X
    }
    return "Unknown";
}

Logger setLogger(Logger logger) {
    std::lock_guard lock(loggerMutex());
    return std::exchange(currentLogger(), std::move(logger));
}

void log(LogId id, LogLevel level, std::string_view message) {
    Logger logger;
    {
        std::lock_guard lock(loggerMutex());
        logger = currentLogger();
    }
    if (logger) {
        logger(LogItem{id, level, message});
        return;
    }
    std::fprintf(stderr, "rrc %s [%d %.*s]: %.*s\n", levelName(level), static_cast<int>(id),
                 static_cast<int>(logIdName(id).size()), logIdName(id).data(),
                 static_cast<int>(message.size()), message.data());
}

Error fail(LogId id, std::string message) {
    logError(id, message);
    return Error{id, std::move(message)};
}

void badResultAccess(const Error& error) {
    std::fprintf(stderr, "rrc: value() taken from a failed Result [%d %.*s]: %s\n",
                 static_cast<int>(error.id), static_cast<int>(logIdName(error.id).size()),
                 logIdName(error.id).data(), error.message.c_str());
    std::abort();
}

} // namespace rrc
