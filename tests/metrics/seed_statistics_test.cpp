#include "metrics/seed_statistics.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

using namespace engine::metrics;

TEST(SeedStatistics, OddCountMedianIsTheMiddleValueWhateverTheOrder) {
    const std::vector<double> v{9.0, 1.0, 5.0, 3.0, 100.0};
    SeedSummary s = summarize(v);
    EXPECT_EQ(s.count, 5u);
    EXPECT_DOUBLE_EQ(s.median, 5.0);  // the outlier 100 does not move it (a mean would be 23.6)
    EXPECT_DOUBLE_EQ(s.min, 1.0);
    EXPECT_DOUBLE_EQ(s.max, 100.0);
    EXPECT_DOUBLE_EQ(s.q1, 3.0);
    EXPECT_DOUBLE_EQ(s.q3, 9.0);
}

TEST(SeedStatistics, EvenCountMedianAveragesTheMiddleTwo) {
    const std::vector<double> v{4.0, 1.0, 3.0, 2.0};
    SeedSummary s = summarize(v);
    EXPECT_DOUBLE_EQ(s.median, 2.5);
    EXPECT_DOUBLE_EQ(s.q1, 1.75);  // type-7 quantiles: 1 + 0.75 x (2 - 1)
    EXPECT_DOUBLE_EQ(s.q3, 3.25);
}

TEST(SeedStatistics, EmptyAndNanValues) {
    SeedSummary none = summarize(std::vector<double>{});
    EXPECT_EQ(none.count, 0u);
    EXPECT_EQ(none.median, 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    SeedSummary s = summarize(std::vector<double>{nan, 2.0, nan});
    EXPECT_EQ(s.count, 1u);
    EXPECT_DOUBLE_EQ(s.median, 2.0);
    EXPECT_DOUBLE_EQ(s.min, 2.0);
    EXPECT_DOUBLE_EQ(s.max, 2.0);
}

TEST(SeedStatistics, RatiosPairSeedsAndSkipZeroDenominators) {
    const std::vector<double> uniform{8.0, 6.0, 30.0, 1.0};
    const std::vector<double> restir{2.0, 3.0, 0.0, 0.5,
                                     7.0};  // seed 3 of ReSTIR is exact; one extra seed
    std::vector<double> r = perSeedRatios(uniform, restir);
    ASSERT_EQ(r.size(), 3u);
    EXPECT_DOUBLE_EQ(r[0], 4.0);
    EXPECT_DOUBLE_EQ(r[1], 2.0);
    EXPECT_DOUBLE_EQ(r[2], 2.0);
    // The median of per-seed ratios differs from the ratio of medians: seeds are paired.
    EXPECT_DOUBLE_EQ(summarize(r).median, 2.0);
}
