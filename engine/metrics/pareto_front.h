// The Pareto front of points measured with uncertainty (cost with an interval, error per seed),
// and which of its members are resolved. A front drawn through medians changes its members from
// run to run when two points are closer than their intervals (issue 42: uniform 1 ray against
// RIS M = 1, 10 % apart in cost and 1 % in error, in the front in two runs of four). Here a point
// leaves the front only when another point *surely* dominates it (no dearer beyond doubt and less
// accurate beyond doubt: both verdicts of median_interval.h), and a member is *resolved* when no
// other point even possibly dominates it; the rest are members "not resolved at this budget".
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>
#include <vector>

#include "metrics/median_interval.h"

namespace engine::metrics {

enum class FrontStatus { Member, Unresolved, Dominated };
std::string_view frontStatusName(FrontStatus s);  // "member", "unresolved", "dominated"

struct FrontInput {
    // costRatio(q, p): cost of q over cost of p, with its interval (1 exactly for the same work).
    std::function<MedianInterval(std::size_t, std::size_t)> costRatio;
    // errors[point][seed]: the seeds are paired (seed s renders every point with the same seed),
    // so q's error over p's is compared per seed.
    std::vector<std::vector<double>> errors;
    double confidence = 0.9;
    double noise = 0.05;  // a difference in error or cost below this is no verdict
};

std::vector<FrontStatus> paretoFront(const FrontInput& in);

}  // namespace engine::metrics
