// Statistics over repeated measurements (one value per seed): a single run's MSE is decided by a
// few outlier pixels, so benchmarks report the median and the spread over seeds, and compare two
// methods by the median of their per-seed ratios (each seed's pair shares the scene and view, so
// the ratio cancels what the seeds have in common).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace engine::metrics {

struct SeedSummary {
    std::size_t count = 0;
    double median = 0.0;        // the middle value; the mean of the middle two for an even count
    double q1 = 0.0, q3 = 0.0;  // quartiles, linear interpolation between order statistics
    double min = 0.0,
           max = 0.0;  // the spread the docs print (with 5 seeds the quartiles are shaky)
};

// Summary of the values (empty input: all zero). NaN values are kept out and not counted.
SeedSummary summarize(std::span<const double> values);

// Per-seed ratios numerator[i] / denominator[i] over the seeds both have (the shorter length);
// a pair with a zero or non-finite denominator is left out.
std::vector<double> perSeedRatios(std::span<const double> numerator,
                                  std::span<const double> denominator);

}  // namespace engine::metrics
