#include "metrics/seed_statistics.h"

#include <algorithm>
#include <cmath>

namespace engine::metrics {

namespace {

// The p-quantile of sorted values, interpolating between neighbours (the "type 7" definition
// of Hyndman & Fan, R's and NumPy's default).
double quantile(const std::vector<double>& sorted, double p) {
    double at = p * double(sorted.size() - 1);
    std::size_t lo = std::size_t(std::floor(at));
    std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (at - double(lo)) * (sorted[hi] - sorted[lo]);
}

}  // namespace

SeedSummary summarize(std::span<const double> values) {
    std::vector<double> v;
    for (double x : values) {
        if (!std::isnan(x)) v.push_back(x);
    }
    SeedSummary s;
    s.count = v.size();
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    s.median = quantile(v, 0.5);
    s.q1 = quantile(v, 0.25);
    s.q3 = quantile(v, 0.75);
    s.min = v.front();
    s.max = v.back();
    return s;
}

std::vector<double> perSeedRatios(std::span<const double> numerator,
                                  std::span<const double> denominator) {
    std::vector<double> out;
    for (std::size_t i = 0; i < std::min(numerator.size(), denominator.size()); ++i) {
        if (denominator[i] == 0.0 || !std::isfinite(denominator[i])) continue;
        out.push_back(numerator[i] / denominator[i]);
    }
    return out;
}

}  // namespace engine::metrics
