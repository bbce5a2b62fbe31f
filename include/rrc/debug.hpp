// GL error and KHR_debug diagnostics routed to rrc's logger.
#pragma once
#include <rrc/gl.hpp>

#include <string_view>

namespace rrc {

struct DebugCounters {
    long glErrors = 0;         // errors returned by glGetError and drained by checkGLErrors()
    long debugErrors = 0;      // KHR_debug messages of type ERROR
    long debugMessages = 0;    // all KHR_debug messages that reached the callback
};

// Routes KHR_debug output of the current context to the logger (errors as LogLevel::Error,
// performance/portability notes as warnings; notifications are dropped).
void installDebugOutput();

// Drains glGetError, logging each error with `where`; returns how many there were.
int checkGLErrors(std::string_view where);

DebugCounters debugCounters();
void resetDebugCounters();

std::string_view glErrorName(GLenum error);

} // namespace rrc
