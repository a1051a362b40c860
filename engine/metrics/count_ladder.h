// Equal cost without re-drawing the dice. A benchmark that renders a row at the count (RIS's M,
// uniform's rays) that costs what the yardstick costs re-renders it at a new count whenever the
// calibration moves a little, and every new count is a new draw of a heavy-tailed error: a 10 %
// change of M moved the median of five seeds' MSE ratios by up to 1.5x (issue 42). So the row is
// rendered at fixed counts, the powers of two on either side of the equal-cost count (a ladder
// every run shares), and its error is interpolated between them in log error against log count
// (Monte Carlo error follows a power of the sample count: MSE ~ 1 / N for independent samples,
// a flatter power where some error does not average away), its time linearly in the count (the
// work is linear in it). Then a calibration that moves the count by 10 % moves the result
// smoothly, by the error's own slope, and the renders are the same from run to run.
#pragma once

#include <cstdint>

namespace engine::metrics {

struct LadderBracket {
    std::uint32_t low = 1, high = 1;  // the powers of two around the count (equal when it is one)
    double logWeight = 0.0;           // log(count / low) / log(high / low): high's share, 0..1
    double linearWeight = 0.0;        // (count - low) / (high - low)
};

// The bracket of `count`, clamped to [1, maxCount] (a power of two's bracket is itself alone).
LadderBracket ladderBracket(double count, std::uint32_t maxCount);

// exp((1 - w) log atLow + w log atHigh) for positive values; linear otherwise (a zero error).
double interpolateLog(double atLow, double atHigh, double weight);
double interpolateLinear(double atLow, double atHigh, double weight);

}  // namespace engine::metrics
