#include "metrics/median_interval.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "metrics/seed_statistics.h"

namespace engine::metrics {

namespace {

// P(X <= k) for X ~ Binomial(n, 1/2).
double binomialHalfCdf(std::size_t n, std::size_t k) {
    double term = std::pow(0.5, double(n));  // C(n, 0) / 2^n
    double sum = 0.0;
    for (std::size_t i = 0; i <= k && i <= n; ++i) {
        sum += term;
        term *= double(n - i) / double(i + 1);
    }
    return sum;
}

}  // namespace

MedianInterval medianInterval(std::span<const double> values, double confidence) {
    std::vector<double> v;
    for (double x : values) {
        if (std::isfinite(x)) v.push_back(x);
    }
    MedianInterval out;
    out.count = v.size();
    if (v.empty()) return out;
    std::sort(v.begin(), v.end());
    out.median = summarize(v).median;
    // [v(k), v(n-1-k)] (0-based) misses the median with probability 2 P(X <= k); take the
    // largest k that keeps the coverage at or above the confidence.
    const std::size_t n = v.size();
    std::size_t k = 0;
    out.covered = 1.0 - 2.0 * binomialHalfCdf(n, 0);
    while (2 * (k + 1) < n - 1) {  // the interval keeps at least two values
        const double covered = 1.0 - 2.0 * binomialHalfCdf(n, k + 1);
        if (covered < confidence) break;
        ++k;
        out.covered = covered;
    }
    out.low = v[k];
    out.high = v[n - 1 - k];
    return out;
}

MedianInterval productInterval(const MedianInterval& a, const MedianInterval& b) {
    MedianInterval out;
    out.low = a.low * b.low;
    out.median = a.median * b.median;
    out.high = a.high * b.high;
    out.covered = a.covered * b.covered;
    out.count = std::min(a.count, b.count);
    return out;
}

Verdict verdictOf(const MedianInterval& ratio, double confidence, double noise) {
    if (ratio.count == 0 || ratio.covered < confidence) return Verdict::Unresolved;
    if (ratio.low > 1.0 + noise) return Verdict::Above;
    if (ratio.high < 1.0 / (1.0 + noise)) return Verdict::Below;
    return Verdict::Unresolved;
}

std::string_view verdictName(Verdict v) {
    switch (v) {
        case Verdict::Above:
            return "> 1";
        case Verdict::Below:
            return "< 1";
        case Verdict::Unresolved:
            break;
    }
    return "unresolved";
}

}  // namespace engine::metrics
