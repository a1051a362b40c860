// The cost model (metrics/cost_model.h) on synthetic timings: known per-kind costs, a machine
// whose speed changes from round to round, noise and a kind that costs nothing.
#include "metrics/cost_model.h"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using engine::metrics::CostModel;
using engine::metrics::fitCostModel;
using engine::metrics::MedianInterval;

namespace {

// Points of a two-method bench: a base of 1000 pixels, then rays or candidates.
const std::vector<std::vector<double>> kCounts = {
    {1000, 0, 64000},  // the yardstick: candidates
    {1000, 1000, 0},   // 1 ray per pixel
    {1000, 16000, 0},  // 16 rays
    {1000, 0, 8000},   // 8 candidates
};
const std::vector<double> kTrueCosts = {2e-3, 1e-3, 5e-5};  // per unit, in ms

double trueTime(const std::vector<double>& counts) {
    double t = 0.0;
    for (std::size_t k = 0; k < counts.size(); ++k) t += kTrueCosts[k] * counts[k];
    return t;
}

// times[point][round]: each round's machine runs at `speed(round)` of its quiet speed.
template <class Speed, class Noise>
std::vector<std::vector<double>> timesOf(std::size_t rounds, Speed speed, Noise noise) {
    std::vector<std::vector<double>> t(kCounts.size());
    for (std::size_t r = 0; r < rounds; ++r) {
        for (std::size_t p = 0; p < kCounts.size(); ++p)
            t[p].push_back(trueTime(kCounts[p]) / speed(r) * noise());
    }
    return t;
}

}  // namespace

TEST(CostModel, ALoadThatScalesWholeRoundsDoesNotMoveTheRelativeCosts) {
    // Every other round at a third of the speed, others at varying speeds: exact relative costs
    // (to the fit's ridge, 1e-9 of the data's scale).
    auto t = timesOf(
        10, [](std::size_t r) { return r % 2 ? 0.33 : 1.0 + 0.1 * double(r); }, [] { return 1.0; });
    CostModel m = fitCostModel(kCounts, t, 0);
    const double unit = trueTime(kCounts[0]);
    for (std::size_t k = 0; k < kTrueCosts.size(); ++k) {
        EXPECT_NEAR(m.perKind[k], kTrueCosts[k] / unit, 1e-6 * kTrueCosts[k] / unit) << k;
        EXPECT_NEAR(m.perKindInterval[k].low, m.perKindInterval[k].high, 1e-9) << k;
    }
    EXPECT_NEAR(m.cost(kCounts[0]), 1.0, 1e-6);
    EXPECT_LT(m.worstResidual, 1e-6);
    // The ratio of two points is the true one, with a zero-width interval.
    auto ratio = m.ratio(kCounts[2], kCounts[0], 0.95);
    EXPECT_NEAR(ratio.median, trueTime(kCounts[2]) / unit, 1e-6);
    EXPECT_NEAR(ratio.high - ratio.low, 0.0, 1e-9);
}

TEST(CostModel, NoisyRoundsGiveAnIntervalAroundTheTruth) {
    std::mt19937 rng(42);
    std::lognormal_distribution<double> noise(0.0, 0.08);  // +-8 % per measurement
    std::uniform_real_distribution<double> load(0.3, 1.0);
    auto t = timesOf(
        16, [&](std::size_t) { return load(rng); }, [&] { return noise(rng); });
    CostModel m = fitCostModel(kCounts, t, 0, 0.95);
    const double unit = trueTime(kCounts[0]);
    // Each kind's interval over the rounds' fits holds its true cost (the base, fitted from
    // intercepts alone, is the least certain: its estimate may be 20 % off at this noise).
    for (std::size_t k = 0; k < kTrueCosts.size(); ++k) {
        const double truth = kTrueCosts[k] / unit;
        EXPECT_LE(m.perKindInterval[k].low, truth) << k;
        EXPECT_GE(m.perKindInterval[k].high, truth) << k;
        EXPECT_NEAR(m.perKind[k], truth, 0.3 * truth) << k;
    }
    // Equal cost for the ray point: the true answer is (64000 x 5e-5 + 2 - 2) / 1e-3 = 3.2 rays
    // per pixel; the model's count lands within 15 %.
    const double rays = (m.cost(kCounts[0]) - m.perKind[0] * 1000) / (m.perKind[1] * 1000);
    EXPECT_NEAR(rays, 3.2, 0.15 * 3.2);
}

TEST(CostModel, AKindThatCostsNothingIsNotGivenANegativeCost) {
    // A fourth kind present in one point but free: plain least squares would go negative on noise.
    std::vector<std::vector<double>> counts = {
        {1000, 0, 64000, 0}, {1000, 1000, 0, 500}, {1000, 16000, 0, 0}, {1000, 0, 8000, 0}};
    std::vector<std::vector<double>> t(counts.size());
    for (std::size_t r = 0; r < 8; ++r) {
        for (std::size_t p = 0; p < counts.size(); ++p) {
            std::vector<double> c(counts[p].begin(), counts[p].begin() + 3);
            t[p].push_back(trueTime(c) * (p == 1 ? 0.97 : 1.0));  // point 1 a little fast
        }
    }
    CostModel m = fitCostModel(counts, t, 0);
    for (double c : m.perKind) EXPECT_GE(c, 0.0);
    EXPECT_EQ(m.perKind[3], 0.0);
}

TEST(CostModel, KindsNoPointUsesCostNothing) {
    std::vector<std::vector<double>> counts = {{1000, 0, 0}, {1000, 4000, 0}};
    std::vector<std::vector<double>> t = {{2.0, 1.0}, {6.0, 3.0}};
    CostModel m = fitCostModel(counts, t, 0);
    EXPECT_NEAR(m.perKind[0], 1.0 / 1000, 1e-12);
    EXPECT_NEAR(m.perKind[1], 2.0 / 4000, 1e-12);
    EXPECT_EQ(m.perKind[2], 0.0);
}

TEST(CostModel, MoreKindsThanPointsStillGivesEveryPointItsTime) {
    // Two settings of one method differ in two kinds at once: the kinds' split is not
    // determined, but each point's modelled cost is its time and the ratio is theirs.
    std::vector<std::vector<double>> counts = {{1000, 32000, 2000, 11000},
                                               {1000, 32000, 3000, 12000}};
    std::vector<std::vector<double>> t = {{4.0, 2.0, 3.0}, {4.4, 2.2, 3.3}};
    CostModel m = fitCostModel(counts, t, 0);
    EXPECT_NEAR(m.cost(counts[0]), 1.0, 1e-6);
    EXPECT_NEAR(m.ratio(counts[1], counts[0], 0.5).median, 1.1, 1e-6);
    for (double c : m.perKind) EXPECT_GE(c, 0.0);
}

TEST(CostModel, DriftWidensARatioByItsKindsRelativeCostsOnly) {
    CostModel m;
    m.perKind = {1.0, 1.0, 0.0};
    m.perRound = {{1.0, 1.0, 0.0}, {1.0, 1.0, 0.0}};
    // Same work: exactly 1 whatever the drift.
    const std::vector<double> a = {1.0, 1.0, 5.0};
    auto same = m.ratio(a, a, 0.5, 0.2);
    EXPECT_DOUBLE_EQ(same.low, 1.0);
    EXPECT_DOUBLE_EQ(same.high, 1.0);
    // Kind 1 only against kind 0 only: the ratio of the two costs, each off by up to 1.2x, so
    // (1/1.2)/1.2 .. 1.2*1.2 around 1.
    const std::vector<double> k0 = {1.0, 0.0, 0.0}, k1 = {0.0, 1.0, 0.0};
    auto both = m.ratio(k1, k0, 0.5, 0.2);
    EXPECT_DOUBLE_EQ(both.median, 1.0);
    EXPECT_NEAR(both.low, 1.0 / 1.44, 1e-12);
    EXPECT_NEAR(both.high, 1.44, 1e-12);
    // A point with 10 % more of kind 1 than the yardstick's mix: (1 + 1.1) / 2 = 1.05, and its
    // extremes put kind 1 at 1.2^2 relative to kind 0: (1 + 1.1 * 1.44) / (1 + 1.44).
    const std::vector<double> mix = {1.0, 1.0, 0.0}, more = {1.0, 1.1, 0.0};
    auto near = m.ratio(more, mix, 0.5, 0.2);
    EXPECT_NEAR(near.median, 1.05, 1e-12);
    EXPECT_NEAR(near.high, (1.0 + 1.1 * 1.44) / (1.0 + 1.44), 1e-12);
    EXPECT_NEAR(near.low, (1.0 + 1.1 / 1.44) / (1.0 + 1.0 / 1.44), 1e-12);
    // No drift: the rounds' interval as before.
    auto none = m.ratio(more, mix, 0.5);
    EXPECT_DOUBLE_EQ(none.low, none.high);
}

TEST(CostModel, DriftAndTheRoundsIntervalSpanBothNotTheirProduct) {
    CostModel m;
    m.perKind = {1.0, 1.0};
    const std::vector<double> k0 = {1.0, 0.0}, k1 = {0.0, 1.0};
    // The box puts kind 1 over kind 0 at 1/1.44 .. 1.44 of the fit's ratio (1 here).
    MedianInterval rounds{0.9, 1.0, 1.1, 0.97, 16};
    auto w = m.widenByDrift(rounds, k1, k0, 0.2);
    EXPECT_DOUBLE_EQ(w.median, 1.0);
    EXPECT_NEAR(w.low, 1.0 / 1.44, 1e-12);  // not 0.9 / 1.44: the drift is the spread of whole
    EXPECT_NEAR(w.high, 1.44, 1e-12);       // runs' fits, their rounds' noise included
    // A rounds' interval wider than the box keeps its ends (a noisy run says so).
    MedianInterval wide{0.5, 1.0, 2.0, 0.97, 16};
    auto kept = m.widenByDrift(wide, k1, k0, 0.2);
    EXPECT_DOUBLE_EQ(kept.low, 0.5);
    EXPECT_DOUBLE_EQ(kept.high, 2.0);
    // A measured ratio (median 1.1) against the model's 1: the box is taken around the median.
    MedianInterval measured{1.05, 1.1, 1.15, 0.97, 16};
    auto around = m.widenByDrift(measured, k1, k0, 0.2);
    EXPECT_NEAR(around.low, 1.1 / 1.44, 1e-12);
    EXPECT_NEAR(around.high, 1.1 * 1.44, 1e-12);
    // A measured ratio's misfit widens the box further, either way.
    auto misfit = m.widenByDrift(measured, k1, k0, 0.2, 0.05);
    EXPECT_NEAR(misfit.low, 1.1 / 1.44 / 1.05, 1e-12);
    EXPECT_NEAR(misfit.high, 1.1 * 1.44 * 1.05, 1e-12);
    // Same work: the interval as measured, whatever the drift.
    auto same = m.widenByDrift(rounds, k0, k0, 0.2);
    EXPECT_DOUBLE_EQ(same.low, 0.9);
    EXPECT_DOUBLE_EQ(same.high, 1.1);
}
