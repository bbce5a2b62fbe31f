// Runs runDemo() in-process with an argument list, capturing stdout and stderr (gtest's fd-level
// capture, so printf output is caught too), and a self-removing temporary folder.
#pragma once
#include "trivial_demo.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rrc::demo::test {

struct RunResult {
    int code = -1;
    std::string out, err;
};

inline RunResult runTrivial(std::vector<std::string> args, DemoDesc desc = trivialDemo()) {
    args.insert(args.begin(), "marble");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    RunResult r;
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    r.code = runDemo(static_cast<int>(args.size()), argv.data(), std::move(desc));
    r.out = ::testing::internal::GetCapturedStdout();
    r.err = ::testing::internal::GetCapturedStderr();
    return r;
}

// A fresh folder under the system temp folder, removed with the object.
class TempDir {
public:
    explicit TempDir(const std::string& tag) {
        path_ = std::filesystem::temp_directory_path() /
                ("rrc_demo_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter()++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() { std::error_code e; std::filesystem::remove_all(path_, e); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string str() const { return path_.string(); }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    static int& counter() { static int n = 0; return n; }
    std::filesystem::path path_;
};

} // namespace rrc::demo::test
