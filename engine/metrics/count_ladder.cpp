#include "metrics/count_ladder.h"

#include <algorithm>
#include <cmath>

namespace engine::metrics {

LadderBracket ladderBracket(double count, std::uint32_t maxCount) {
    LadderBracket b;
    const double c = std::clamp(std::isfinite(count) ? count : 1.0, 1.0, double(maxCount));
    std::uint32_t low = 1;
    while (double(low) * 2.0 <= c && low * 2u <= maxCount) low *= 2u;
    b.low = low;
    b.high = double(low) == c || low * 2u > maxCount ? low : low * 2u;
    if (b.high > b.low) {
        b.logWeight = std::log(c / double(b.low)) / std::log(double(b.high) / double(b.low));
        b.linearWeight = (c - double(b.low)) / double(b.high - b.low);
    }
    return b;
}

double interpolateLog(double atLow, double atHigh, double weight) {
    if (weight <= 0.0) return atLow;
    if (weight >= 1.0) return atHigh;
    if (!(atLow > 0.0 && atHigh > 0.0)) return interpolateLinear(atLow, atHigh, weight);
    return std::exp((1.0 - weight) * std::log(atLow) + weight * std::log(atHigh));
}

double interpolateLinear(double atLow, double atHigh, double weight) {
    return atLow + weight * (atHigh - atLow);
}

}  // namespace engine::metrics
