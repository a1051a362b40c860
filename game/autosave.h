// Autosave: every few minutes, if the world changed since it was last written (by a save or
// an autosave), it goes to a separate file (`STEM.autosave.toml` beside the save) — never
// over the user's own save. Time is passed in: wall-clock seconds when playing live, the
// fixed script clock when replaying a script.
#pragma once

#include <cstdint>
#include <filesystem>

namespace game {

std::filesystem::path autosavePath(const std::filesystem::path& savePath);

class Autosave {
public:
    // intervalSeconds <= 0 disables autosaving.
    explicit Autosave(double intervalSeconds) : mInterval(intervalSeconds) {}

    // `worldVersion` counts the world's changes. True when an autosave is due now.
    bool due(double nowSeconds, std::uint64_t worldVersion) const;
    // The world at `worldVersion` was written (saved or autosaved) at `nowSeconds`.
    void written(double nowSeconds, std::uint64_t worldVersion);
    // A write failed: try again one interval from now.
    void postpone(double nowSeconds) { mLastWrite = nowSeconds; }

private:
    double mInterval;
    double mLastWrite = 0.0;
    std::uint64_t mWrittenVersion = 0;
};

}  // namespace game
