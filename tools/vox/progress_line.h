// One progress line on stderr for long runs: "label 37/151  2.1 frame/s  elapsed 0:17  ETA 0:55".
// On a terminal it rewrites itself in place (at most a few times a second); into a file or pipe
// it writes a line per tenth of the work, so logs stay short.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace vox {

class ProgressLine {
public:
    ProgressLine(std::string label, std::uint64_t total, std::string unit = "frame");
    // `done` units finished; `note` is appended (e.g. "warm-up").
    void update(std::uint64_t done, const std::string& note = {});
    // A message of its own line, without tearing the progress line.
    void note(const std::string& text);
    // Ends the line (on a terminal) and returns the seconds since construction.
    double finish();

private:
    using Clock = std::chrono::steady_clock;
    std::string mLabel, mUnit;
    std::uint64_t mTotal;
    Clock::time_point mStart, mLastPrint;
    std::uint64_t mLastDecile = 0;
    bool mTerminal;
    bool mPrinted = false;
};

// "1:05", "1:02:03".
std::string formatDuration(double seconds);

}  // namespace vox
