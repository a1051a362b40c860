// A distribution-free confidence interval for the median of repeated measurements, and the
// verdict a benchmark may draw from it. Timings on a shared machine are skewed and drift, so no
// normal model is assumed: the interval is the pair of order statistics that covers the median
// with at least the asked confidence (the sign test's interval; Conover, "Practical
// Nonparametric Statistics", 3.6). With too few values for that confidence the interval is the
// whole range and reports it (`covered` below the confidence): a verdict needs more repeats.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace engine::metrics {

struct MedianInterval {
    double low = 0.0, median = 0.0, high = 0.0;
    double covered =
        0.0;  // the interval's actual coverage (>= the asked confidence when enough values)
    std::size_t count = 0;
};

// Over the finite values (NaN and infinities are left out). Empty input: all zero.
MedianInterval medianInterval(std::span<const double> values, double confidence = 0.95);

// The interval of a product of two independent positive quantities, each with its interval
// (a ratio of errors times a ratio of costs): ends multiply. The coverage is the product of the
// two (both must hold).
MedianInterval productInterval(const MedianInterval& a, const MedianInterval& b);

// What a ratio's interval allows one to say against 1: above (every plausible value > 1),
// below, or unresolved (the interval contains 1, or is too wide to have its confidence).
enum class Verdict { Above, Below, Unresolved };
// `noise`: the smallest difference worth a verdict (criterion.rs's noise threshold): the interval
// must also exclude [1 / (1 + noise), 1 + noise], so a ratio whose interval ends at 1.00 in one
// run and 1.04 in the next is "unresolved" in both rather than flipping.
Verdict verdictOf(const MedianInterval& ratio, double confidence = 0.95, double noise = 0.0);
std::string_view verdictName(Verdict v);  // "> 1", "< 1", "unresolved"

}  // namespace engine::metrics
