#include "metrics/interleaved_rounds.h"

#include <cstdint>
#include <gtest/gtest.h>
#include <random>
#include <vector>

#include "metrics/seed_statistics.h"

using namespace engine::metrics;

namespace {

// A shared machine in miniature: every measurement is 1 % slower than the one before (others'
// work piling up), with seeded noise of up to +-5 %.
struct DriftingMachine {
    std::vector<double> trueTimes;
    double slowdown = 1.0;
    std::mt19937 rng{7};
    double measure(std::size_t i) {
        slowdown *= 1.01;
        std::uniform_real_distribution<double> noise(0.95, 1.05);
        return trueTimes[i] * slowdown * noise(rng);
    }
};

}  // namespace

TEST(MedianInterval, OrderStatisticsOfTheSignTest) {
    std::vector<double> v;
    for (int i = 20; i >= 1; --i) v.push_back(double(i));  // 1..20, unsorted
    MedianInterval m = medianInterval(v);
    EXPECT_DOUBLE_EQ(m.median, 10.5);
    // n = 20 at 95 %: the 6th and 15th smallest (P(X <= 5) = 0.0207 for Binomial(20, 1/2)).
    EXPECT_DOUBLE_EQ(m.low, 6.0);
    EXPECT_DOUBLE_EQ(m.high, 15.0);
    EXPECT_NEAR(m.covered, 1.0 - 2.0 * 0.020695, 1e-5);
}

TEST(MedianInterval, TooFewValuesCannotReachTheConfidence) {
    const std::vector<double> five{1.1, 1.2, 1.3, 1.4, 1.5};
    MedianInterval m = medianInterval(five);
    EXPECT_DOUBLE_EQ(m.low, 1.1);
    EXPECT_DOUBLE_EQ(m.high, 1.5);
    EXPECT_DOUBLE_EQ(m.covered, 1.0 - 2.0 / 32.0);       // min-max of 5 covers 93.75 %
    EXPECT_EQ(verdictOf(m, 0.95), Verdict::Unresolved);  // all above 1, but not at 95 %
    EXPECT_EQ(verdictOf(m, 0.90), Verdict::Above);
}

TEST(MedianInterval, VerdictNeedsTheWholeIntervalOnOneSide) {
    EXPECT_EQ(verdictOf(medianInterval(std::vector<double>{1.2, 1.3, 1.1, 1.25, 1.4, 1.15, 1.3})),
              Verdict::Above);
    EXPECT_EQ(verdictOf(medianInterval(std::vector<double>{0.8, 0.7, 0.9, 0.85, 0.75, 0.6, 0.8})),
              Verdict::Below);
    EXPECT_EQ(verdictOf(medianInterval(std::vector<double>{0.9, 1.3, 1.1, 1.2, 1.4, 1.15, 1.3})),
              Verdict::Unresolved);
    EXPECT_EQ(verdictName(Verdict::Unresolved), "unresolved");
}

TEST(MedianInterval, ANoiseThresholdKeepsBorderlineIntervalsUnresolved) {
    MedianInterval edge{1.01, 1.10, 1.17, 0.95, 7};  // the lower end just above 1
    EXPECT_EQ(verdictOf(edge, 0.9), Verdict::Above);
    EXPECT_EQ(verdictOf(edge, 0.9, 0.05), Verdict::Unresolved);
    MedianInterval clear{1.06, 1.3, 1.5, 0.95, 7};
    EXPECT_EQ(verdictOf(clear, 0.9, 0.05), Verdict::Above);
    MedianInterval below{0.5, 0.8, 0.96, 0.95, 7};  // 0.96 > 1 / 1.05: within the noise
    EXPECT_EQ(verdictOf(below, 0.9, 0.05), Verdict::Unresolved);
    below.high = 0.94;
    EXPECT_EQ(verdictOf(below, 0.9, 0.05), Verdict::Below);
}

TEST(MedianInterval, ProductMultipliesTheEnds) {
    MedianInterval a{0.5, 1.0, 2.0, 0.96, 6}, b{1.1, 1.2, 1.3, 0.98, 8};
    MedianInterval p = productInterval(a, b);
    EXPECT_DOUBLE_EQ(p.low, 0.55);
    EXPECT_DOUBLE_EQ(p.high, 2.6);
    EXPECT_DOUBLE_EQ(p.median, 1.2);
    EXPECT_NEAR(p.covered, 0.96 * 0.98, 1e-12);
    EXPECT_EQ(p.count, 6u);
}

TEST(InterleavedRounds, DriftFallsOnEveryAlternativeAlike) {
    // B is truly 1.2x A. Measured in blocks (all A, then all B) the drift would add ~25 % to B.
    DriftingMachine m{{10.0, 12.0}};
    InterleavedTimes t =
        measureInterleaved(2, [&](std::size_t i) { return m.measure(i); }, {1, 6, 24, 0.95, 0.02});
    ASSERT_EQ(t.ratioToFirst.size(), 2u);
    EXPECT_NEAR(t.ratioToFirst[1].median, 1.2, 0.03);
    EXPECT_LE(t.ratioToFirst[1].low, 1.2 * 1.02);
    EXPECT_GE(t.ratioToFirst[1].high, 1.2 / 1.02);
    EXPECT_EQ(verdictOf(t.ratioToFirst[1]), Verdict::Above);

    DriftingMachine blocked{{10.0, 12.0}};
    std::vector<double> a, b;
    for (int r = 0; r < 24; ++r) a.push_back(blocked.measure(0));
    for (int r = 0; r < 24; ++r) b.push_back(blocked.measure(1));
    EXPECT_GT(medianInterval(perSeedRatios(b, a)).median, 1.4);  // what interleaving removes
}

TEST(InterleavedRounds, EqualAlternativesAreNotCalledAWin) {
    DriftingMachine m{{10.0, 10.0, 10.0}};
    InterleavedTimes t = measureInterleaved(3, [&](std::size_t i) { return m.measure(i); });
    for (std::size_t i = 1; i < 3; ++i) {
        EXPECT_EQ(verdictOf(t.ratioToFirst[i]), Verdict::Unresolved) << i;
        EXPECT_LT(t.ratioToFirst[i].low, 1.0);
        EXPECT_GT(t.ratioToFirst[i].high, 1.0);
    }
}

TEST(InterleavedRounds, WarmupIsDiscardedAndAQuietMachineStopsEarly) {
    std::vector<int> calls(2, 0);
    auto measure = [&](std::size_t i) { return ++calls[i] == 1 ? 1000.0 : (i == 0 ? 4.0 : 6.0); };
    InterleavedTimes t = measureInterleaved(2, measure, {1, 6, 24, 0.95, 0.01});
    EXPECT_TRUE(t.converged);
    EXPECT_EQ(t.rounds, 6u);  // noise-free: narrow at the first round that can have 95 %
    EXPECT_EQ(calls[0], 7);   // + the warm-up round
    for (double x : t.times[0]) EXPECT_EQ(x, 4.0);
    EXPECT_DOUBLE_EQ(t.ratioToFirst[1].median, 1.5);
}

TEST(InterleavedRounds, OrderAlternatesEveryRound) {
    std::vector<std::size_t> order;
    measureInterleaved(3,
                       [&](std::size_t i) {
                           order.push_back(i);
                           return 1.0;
                       },
                       {0, 2, 2, 0.95, 0.05});
    EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 2, 1, 0}));
}
