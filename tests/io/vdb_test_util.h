// Helpers shared by the io tests: a scratch folder per test, the check every failure message
// must pass (one line that starts with the file's path), a VDB file's bytes to compare.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <unistd.h>

namespace vox_test {

namespace fs = std::filesystem;

class ScratchDir {
public:
    explicit ScratchDir(const std::string& name) {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : name;
        mPath =
            fs::path(testing::TempDir()) / ("vox_io_" + test + "_" + std::to_string(::getpid()));
        fs::remove_all(mPath);
        fs::create_directories(mPath);
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    fs::path operator/(const std::string& file) const { return mPath / file; }
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

// The folder with the real files nobody here wrote (../shared/data/vdb beside the checkout).
inline fs::path sharedVdbDir() { return fs::path(VOX_SHARED_VDB_DIR); }

inline ::testing::AssertionResult isOneLineNamingFile(const std::string& message,
                                                      const fs::path& file) {
    if (message.find('\n') != std::string::npos)
        return ::testing::AssertionFailure() << "more than one line: " << message;
    if (message.rfind(file.string(), 0) != 0)
        return ::testing::AssertionFailure()
               << "does not start with " << file.string() << ": " << message;
    return ::testing::AssertionSuccess();
}

// A VDB file's bytes but its header's UUID, which OpenVDB makes anew for every file (after the
// magic number, the file and library versions and the grid-offsets flag: bytes 21-56), so two
// exports of one world compare equal.
inline std::string vdbBytesWithoutUuid(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), {}};
    if (bytes.size() > 57) std::fill(bytes.begin() + 21, bytes.begin() + 57, '-');
    return bytes;
}

}  // namespace vox_test
