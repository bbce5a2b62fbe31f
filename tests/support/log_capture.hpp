// Captures rrc log items for the lifetime of the object, so tests can assert on message ids.
#pragma once
#include <rrc/log.hpp>

#include <string>
#include <vector>

namespace rrc::test {

struct CapturedLog {
    LogId id;
    LogLevel level;
    std::string message;
};

class LogCapture {
public:
    LogCapture() {
        previous_ = setLogger([this](const LogItem& item) {
            items.push_back({item.id, item.level, std::string(item.message)});
        });
    }
    ~LogCapture() { setLogger(std::move(previous_)); }
    LogCapture(const LogCapture&) = delete;
    LogCapture& operator=(const LogCapture&) = delete;

    bool has(LogId id) const {
        for (auto& i : items) if (i.id == id) return true;
        return false;
    }
    std::vector<CapturedLog> items;

private:
    Logger previous_;
};

} // namespace rrc::test
