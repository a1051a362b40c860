// The count ladder (metrics/count_ladder.h): brackets of powers of two, and interpolation that
// moves smoothly with the count and recovers a power law exactly.
#include "metrics/count_ladder.h"

#include <cmath>
#include <gtest/gtest.h>

using engine::metrics::interpolateLog;
using engine::metrics::ladderBracket;

TEST(CountLadder, BracketsAreThePowersOfTwoAroundTheCount) {
    auto b = ladderBracket(98.0, 1024);
    EXPECT_EQ(b.low, 64u);
    EXPECT_EQ(b.high, 128u);
    EXPECT_NEAR(b.logWeight, std::log2(98.0 / 64.0), 1e-12);
    EXPECT_NEAR(b.linearWeight, 34.0 / 64.0, 1e-12);
    // A power of two is its own bracket; below 1 and above the knob's range clamp.
    auto exact = ladderBracket(128.0, 1024);
    EXPECT_EQ(exact.low, 128u);
    EXPECT_EQ(exact.high, 128u);
    EXPECT_EQ(exact.logWeight, 0.0);
    auto tiny = ladderBracket(0.3, 1024);
    EXPECT_EQ(tiny.low, 1u);
    EXPECT_EQ(tiny.high, 1u);
    auto huge = ladderBracket(5000.0, 1024);
    EXPECT_EQ(huge.low, 1024u);
    EXPECT_EQ(huge.high, 1024u);
    auto rays = ladderBracket(5.6, 4096);
    EXPECT_EQ(rays.low, 4u);
    EXPECT_EQ(rays.high, 8u);
}

TEST(CountLadder, APowerLawIsRecoveredExactlyBetweenTheRungs) {
    // MSE = 3 / N^0.8 at the rungs: the interpolation gives it at any count between.
    auto mse = [](double n) { return 3.0 / std::pow(n, 0.8); };
    for (double n : {65.0, 90.0, 98.0, 111.0, 127.0}) {
        auto b = ladderBracket(n, 1024);
        EXPECT_NEAR(interpolateLog(mse(b.low), mse(b.high), b.logWeight), mse(n), 1e-12 * mse(n))
            << n;
    }
}

TEST(CountLadder, TheResultIsContinuousAcrossARung) {
    // Just below and at 128 (where the bracket changes from 64-128 to 128 alone, then 128-256):
    // the interpolated value does not jump.
    auto value = [](std::uint32_t rung) { return rung == 64 ? 2.0 : rung == 128 ? 1.3 : 0.5; };
    auto at = [&](double n) {
        auto b = ladderBracket(n, 1024);
        return interpolateLog(value(b.low), value(b.high), b.logWeight);
    };
    EXPECT_NEAR(at(127.999), 1.3, 1e-4);
    EXPECT_DOUBLE_EQ(at(128.0), 1.3);
    EXPECT_NEAR(at(128.001), 1.3, 1e-4);
}
