// Timing several alternatives the way trusted benchmarks do, so that ratios between them hold
// from run to run on a shared machine: rounds of one measurement per alternative, the order
// reversed every other round (A B C, C B A, ...: a drift of the machine's speed during a round
// falls on every alternative alike), warm-up rounds discarded, and more rounds until the ratio of
// every alternative to the first one has a narrow enough interval (median of per-round ratios,
// median_interval.h) or the round budget runs out. Each ratio is per round, between measurements
// taken seconds apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "metrics/median_interval.h"

namespace engine::metrics {

struct RoundsPlan {
    std::uint32_t warmupRounds = 1;  // measured and thrown away (caches, pipelines, clocks)
    std::uint32_t minRounds = 6;     // fewer cannot give a 95 % interval for a median
    std::uint32_t maxRounds = 24;
    double confidence = 0.95;
    double relativeHalfWidth = 0.05;  // stop once every ratio's (high - low) / 2 <= this x median
};

struct InterleavedTimes {
    std::vector<std::vector<double>> times;  // [alternative][round], warm-up excluded
    std::vector<MedianInterval>
        ratioToFirst;  // per alternative: time / the first's time, per round
    std::uint32_t rounds = 0;
    bool converged = false;  // every ratio reached the half width within the budget
};

// measure(i) measures alternative i once and returns its time (any unit, > 0).
InterleavedTimes measureInterleaved(std::size_t alternatives,
                                    const std::function<double(std::size_t)>& measure,
                                    const RoundsPlan& plan = {});

}  // namespace engine::metrics
