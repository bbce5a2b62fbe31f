// The malformed-glTF corpus (tests/data/bad_gltf, written by scripts/make_bad_gltf.py): every file
// in manifest.json must fail to load with SceneInvalid or SceneLoadFailed, a message naming the
// file, and the manifest's "expect" word (case-insensitive). Skips when the corpus is absent.
#include "support/log_capture.hpp"

#include "scene.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace rrc::test {
namespace {

const std::string kCorpus = std::string(RRC_SCENE_TEST_DATA) + "/bad_gltf";

struct CorpusEntry {
    std::string file, defect, expect;
};

// Names the file in gtest output instead of dumping the struct's bytes.
void PrintTo(const CorpusEntry& entry, std::ostream* os) { *os << entry.file; }

std::vector<CorpusEntry> manifest() {
    std::ifstream in(kCorpus + "/manifest.json");
    if (!in) return {{"", "manifest.json not found in " + kCorpus, ""}};  // one entry that skips
    const auto json = nlohmann::json::parse(in, nullptr, false);
    std::vector<CorpusEntry> entries;
    if (json.is_array())
        for (const auto& e : json)
            entries.push_back({e.value("file", ""), e.value("defect", ""), e.value("expect", "")});
    if (entries.empty()) entries.push_back({"", "manifest.json is empty or unreadable", ""});
    return entries;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

class SceneCorpus : public ::testing::TestWithParam<CorpusEntry> {};

TEST_P(SceneCorpus, Rejects) {
    const CorpusEntry& entry = GetParam();
    if (entry.file.empty()) GTEST_SKIP() << entry.defect << " (run scripts/make_bad_gltf.py)";
    const std::string path = kCorpus + "/" + entry.file;
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    LogCapture log;
    auto result = scene::loadScene(path);
    ASSERT_FALSE(result.ok()) << entry.file << " loaded despite: " << entry.defect;
    const Error& error = result.error();
    EXPECT_TRUE(error.id == LogId::SceneInvalid || error.id == LogId::SceneLoadFailed) << logIdName(error.id);
    EXPECT_NE(error.message.find(entry.file), std::string::npos) << error.message;
    EXPECT_NE(lower(error.message).find(lower(entry.expect)), std::string::npos)
        << "expected '" << entry.expect << "' (" << entry.defect << ") in: " << error.message;
    EXPECT_EQ(log.items.size(), 1u);
    std::printf("%s\n", error.message.c_str());
}

std::string testName(const ::testing::TestParamInfo<CorpusEntry>& info) {
    std::string name = info.param.file.empty() ? "manifest_missing" : info.param.file;
    std::replace_if(name.begin(), name.end(), [](unsigned char c) { return !std::isalnum(c); }, '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(BadGltf, SceneCorpus, ::testing::ValuesIn(manifest()), testName);

} // namespace
} // namespace rrc::test
