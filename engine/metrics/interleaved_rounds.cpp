#include "metrics/interleaved_rounds.h"

#include "metrics/seed_statistics.h"

namespace engine::metrics {

namespace {

std::vector<MedianInterval> ratiosToFirst(const std::vector<std::vector<double>>& times,
                                          double confidence) {
    std::vector<MedianInterval> out;
    for (const std::vector<double>& t : times)
        out.push_back(medianInterval(perSeedRatios(t, times[0]), confidence));
    return out;
}

bool narrowEnough(const std::vector<MedianInterval>& ratios, const RoundsPlan& plan) {
    for (const MedianInterval& r : ratios) {
        if (r.covered < plan.confidence) return false;
        if ((r.high - r.low) / 2.0 > plan.relativeHalfWidth * r.median) return false;
    }
    return true;
}

}  // namespace

InterleavedTimes measureInterleaved(std::size_t alternatives,
                                    const std::function<double(std::size_t)>& measure,
                                    const RoundsPlan& plan) {
    InterleavedTimes out;
    out.times.resize(alternatives);
    if (alternatives == 0) return out;
    for (std::uint32_t round = 0; round < plan.warmupRounds + plan.maxRounds; ++round) {
        const bool reversed = round % 2 == 1;
        std::vector<double> times(alternatives);
        for (std::size_t k = 0; k < alternatives; ++k) {
            const std::size_t i = reversed ? alternatives - 1 - k : k;
            times[i] = measure(i);
        }
        if (round < plan.warmupRounds) continue;
        for (std::size_t i = 0; i < alternatives; ++i) out.times[i].push_back(times[i]);
        ++out.rounds;
        if (out.rounds < plan.minRounds) continue;
        out.ratioToFirst = ratiosToFirst(out.times, plan.confidence);
        if (narrowEnough(out.ratioToFirst, plan)) {
            out.converged = true;
            break;
        }
    }
    out.ratioToFirst = ratiosToFirst(out.times, plan.confidence);
    return out;
}

}  // namespace engine::metrics
