// Statistics the estimator tests share: the mean of independent runs and its standard error.
#pragma once

#include <cmath>
#include <vector>

namespace gpu_testing {

struct MeanAndError {
    double mean = 0.0, standardError = 0.0;
};

// Mean of independent values (one per seed or run) and the standard error of that mean.
inline MeanAndError meanOfMeans(const std::vector<double>& values) {
    MeanAndError m;
    for (double v : values) m.mean += v / double(values.size());
    double var = 0.0;
    for (double v : values) var += (v - m.mean) * (v - m.mean);
    m.standardError = std::sqrt(var / double(values.size() - 1) / double(values.size()));
    return m;
}

}  // namespace gpu_testing
