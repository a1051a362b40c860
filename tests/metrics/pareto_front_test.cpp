// The Pareto front with intervals (metrics/pareto_front.h) on synthetic points: clear members,
// a clearly dominated point, and two points closer than their intervals.
#include "metrics/pareto_front.h"

#include <gtest/gtest.h>

using engine::metrics::FrontInput;
using engine::metrics::FrontStatus;
using engine::metrics::MedianInterval;
using engine::metrics::paretoFront;

namespace {

// Costs known to within a relative half width `spread`; their ratio's interval multiplies out.
FrontInput inputOf(const std::vector<double>& cost, double spread,
                   std::vector<std::vector<double>> errors) {
    FrontInput in;
    in.costRatio = [cost, spread](std::size_t q, std::size_t p) {
        const double r = cost[q] / cost[p];
        if (cost[q] == cost[p]) return MedianInterval{1.0, 1.0, 1.0, 1.0, 10};
        return MedianInterval{r / (1.0 + spread), r, r * (1.0 + spread), 0.97, 10};
    };
    in.errors = std::move(errors);
    return in;
}

// Five paired seeds of an error around `e`, each seed the same factor off (seeds are paired).
std::vector<double> seeds(double e) { return {e * 0.8, e * 0.9, e, e * 1.1, e * 1.3}; }

}  // namespace

TEST(ParetoFront, ClearTradeOffsAreResolvedMembersAndAWorseDearerPointIsDominated) {
    // 0: cheap and inaccurate; 1: 4x the cost, half the error; 2: 4x the cost of 1, half again;
    // 3: as dear as 2 and worse than 1.
    auto in = inputOf({1, 4, 16, 16}, 0.05, {seeds(8), seeds(4), seeds(2), seeds(5)});
    auto s = paretoFront(in);
    EXPECT_EQ(s[0], FrontStatus::Member);
    EXPECT_EQ(s[1], FrontStatus::Member);
    EXPECT_EQ(s[2], FrontStatus::Member);
    EXPECT_EQ(s[3], FrontStatus::Dominated);
}

TEST(ParetoFront, PointsCloserThanTheirIntervalsAreUnresolvedMembersWhicheverMedianWins) {
    // 0 and 1: 10 % apart in cost with a 15 % interval, 1 % apart in error: neither rules the
    // other out, in either order of their medians.
    for (double second : {1.1, 0.9}) {
        auto in = inputOf({1.0, second, 8.0}, 0.15, {seeds(4.0), seeds(3.96), seeds(1.0)});
        auto s = paretoFront(in);
        EXPECT_EQ(s[0], FrontStatus::Unresolved) << second;
        EXPECT_EQ(s[1], FrontStatus::Unresolved) << second;
        EXPECT_EQ(s[2], FrontStatus::Member) << second;
    }
}

TEST(ParetoFront, TheSameWorkWithBetterErrorInEverySeedDominates) {
    // Point and area lights of one method have the same counted work: the cost ratio is 1 with
    // no interval, and the error decides.
    auto in = inputOf({2.0, 2.0}, 0.15, {seeds(3.0), seeds(2.0)});
    auto s = paretoFront(in);
    EXPECT_EQ(s[0], FrontStatus::Dominated);
    EXPECT_EQ(s[1], FrontStatus::Member);
}

TEST(ParetoFront, ErrorsWhoseSeedsDisagreeDoNotDominate) {
    // Same cost, the second better in three seeds and worse in two: no verdict on the error, so
    // both stay, unresolved.
    auto in = inputOf({2.0, 2.0}, 0.15, {{1, 1, 1, 1, 1}, {0.5, 0.5, 0.5, 2, 2}});
    auto s = paretoFront(in);
    EXPECT_EQ(s[0], FrontStatus::Unresolved);
    EXPECT_EQ(s[1], FrontStatus::Unresolved);
}

TEST(ParetoFront, ThreeSeedsCannotResolveAt90PerCent) {
    // The min-max of three seeds covers the median with 75 %: even a point better in every seed
    // at the same cost does not dominate, and both stay as unresolved members.
    auto in = inputOf({2.0, 2.0}, 0.15, {{3, 3, 3}, {1, 1, 1}});
    auto s = paretoFront(in);
    EXPECT_EQ(s[0], FrontStatus::Unresolved);
    EXPECT_EQ(s[1], FrontStatus::Unresolved);
}
