#include "progress_line.h"

#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

namespace vox {

std::string formatDuration(double seconds) {
    auto s = static_cast<long long>(std::llround(std::max(0.0, seconds)));
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
    return fmt::format("{}:{:02}", s / 60, s % 60);
}

ProgressLine::ProgressLine(std::string label, std::uint64_t total, std::string unit)
    : mLabel(std::move(label)),
      mUnit(std::move(unit)),
      mTotal(std::max<std::uint64_t>(total, 1)),
      mStart(Clock::now()),
      mLastPrint(mStart),
      mTerminal(isatty(fileno(stderr)) != 0) {}

void ProgressLine::update(std::uint64_t done, const std::string& note) {
    auto now = Clock::now();
    std::uint64_t decile = done * 10 / mTotal;
    if (mTerminal) {
        if (done < mTotal && now - mLastPrint < std::chrono::milliseconds(250)) return;
    } else if (decile == mLastDecile && done < mTotal) {
        return;
    }
    mLastPrint = now;
    mLastDecile = decile;
    double elapsed = std::chrono::duration<double>(now - mStart).count();
    double rate = elapsed > 0.0 ? double(done) / elapsed : 0.0;
    std::string eta =
        rate > 0.0 ? formatDuration(double(mTotal - std::min(done, mTotal)) / rate) : "?";
    std::string line =
        fmt::format("{} {}/{}  {:.2f} {}/s  elapsed {}  ETA {}{}{}", mLabel, done, mTotal, rate,
                    mUnit, formatDuration(elapsed), eta, note.empty() ? "" : "  ", note);
    // Pad over the previous, possibly longer, line.
    if (mTerminal)
        std::fprintf(stderr, "\r%-78s", line.c_str());
    else
        std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
    mPrinted = true;
}

void ProgressLine::note(const std::string& text) {
    if (mTerminal && mPrinted) std::fprintf(stderr, "\r%-78s\r", "");
    std::fprintf(stderr, "%s\n", text.c_str());
    mLastPrint = Clock::time_point{};  // redraw the progress line on the next update
}

double ProgressLine::finish() {
    if (mTerminal && mPrinted) std::fprintf(stderr, "\n");
    return std::chrono::duration<double>(Clock::now() - mStart).count();
}

}  // namespace vox
