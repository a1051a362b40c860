#include "metrics/image_metrics.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

using namespace engine::metrics;

namespace {

// Two 2x1 images, worked by hand below. Alpha differs on purpose: it must not count.
const std::vector<glm::vec4> kA = {{1.0f, 0.5f, 0.0f, 1.0f}, {0.0f, 0.0f, 2.0f, 0.0f}};
const std::vector<glm::vec4> kB = {{0.5f, 0.5f, 0.25f, 0.3f}, {0.0f, 1.0f, 0.0f, 7.0f}};

// The value of a Result that must hold one (the test fails otherwise).
template <typename T>
T get(engine::Result<T> r) {
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? std::move(r).value() : T{};
}

ImageView view(const std::vector<glm::vec4>& p, std::uint32_t w, std::uint32_t h) {
    return {p, w, h};
}

std::vector<glm::vec4> noiseImage(std::uint32_t n, std::uint32_t seed) {
    std::vector<glm::vec4> p(n);
    std::uint32_t s = seed;
    auto next = [&] {
        s = s * 1664525u + 1013904223u;
        return float(s >> 8) / float(1 << 24);
    };
    for (auto& v : p) v = glm::vec4(next() * 2.0f, next(), next() * 0.1f, next());
    return p;
}

}  // namespace

// Differences: pixel 0 (0.5, 0, -0.25), pixel 1 (0, -1, 2).
TEST(ImageMetrics, HandComputedTinyImage) {
    auto e = compareImages(view(kA, 2, 1), view(kB, 2, 1));
    ASSERT_TRUE(e.ok()) << e.error().message;
    // thesis eqs. 1-2: PSE = 0.25 + 0 + 0.0625 and 0 + 1 + 4; MSE = 5.3125 / (2 * 3)
    EXPECT_DOUBLE_EQ(e->mse, 5.3125 / 6.0);
    // thesis eqs. 3-4: PAE = 0.75 and 3; MAE = 3.75 / 6
    EXPECT_DOUBLE_EQ(e->mae, 0.625);
    // RMAE: |a-b| / (|b| + 0.01) per channel, the last one against a black reference channel
    double rmae =
        (0.5 / 0.51 + 0.0 / 0.51 + 0.25 / 0.26 + 0.0 / 0.01 + 1.0 / 1.01 + 2.0 / 0.01) / 6.0;
    EXPECT_NEAR(e->rmae, rmae, 1e-12);
    EXPECT_NEAR(e->rmae, 202.93202963 / 6.0, 1e-8);  // 0.98039216 + 0.96153846 + 0.99009901 + 200
    EXPECT_EQ(e->pixels, 2u);
    EXPECT_EQ(e->nonFinitePixels, 0u);

    EXPECT_DOUBLE_EQ(pixelSquaredError(kA[1], kB[1]), 5.0);
    EXPECT_DOUBLE_EQ(pixelAbsoluteError(kA[0], kB[0]), 0.75);
    EXPECT_DOUBLE_EQ(get(meanSquaredError(view(kA, 2, 1), view(kB, 2, 1))), 5.3125 / 6.0);
    EXPECT_DOUBLE_EQ(get(meanAbsoluteError(view(kA, 2, 1), view(kB, 2, 1))), 0.625);
    EXPECT_NEAR(get(relativeMeanAbsoluteError(view(kA, 2, 1), view(kB, 2, 1))), rmae, 1e-12);
}

TEST(ImageMetrics, IdenticalImagesHaveZeroError) {
    auto a = noiseImage(64 * 16, 1);
    auto e = compareImages(view(a, 64, 16), view(a, 64, 16));
    ASSERT_TRUE(e.ok());
    EXPECT_EQ(e->mae, 0.0);
    EXPECT_EQ(e->mse, 0.0);
    EXPECT_EQ(e->rmae, 0.0);
}

TEST(ImageMetrics, MaeAndMseAreSymmetricRmaeIsNot) {
    auto a = noiseImage(40 * 30, 2), b = noiseImage(40 * 30, 3);
    auto ab = get(compareImages(view(a, 40, 30), view(b, 40, 30)));
    auto ba = get(compareImages(view(b, 40, 30), view(a, 40, 30)));
    EXPECT_GT(ab.mae, 0.0);
    EXPECT_GT(ab.mse, 0.0);
    EXPECT_DOUBLE_EQ(ab.mae, ba.mae);
    EXPECT_DOUBLE_EQ(ab.mse, ba.mse);
    EXPECT_NE(ab.rmae, ba.rmae) << "RMAE divides by the reference";
    // MSE >= MAE^2 (Jensen), MAE <= sqrt(MSE).
    EXPECT_GE(ab.mse, ab.mae * ab.mae);
}

TEST(ImageMetrics, ScalingScalesTheErrors) {
    auto a = noiseImage(100, 4), b = noiseImage(100, 5);
    std::vector<glm::vec4> a3 = a, b3 = b;
    for (auto& p : a3) p *= 3.0f;
    for (auto& p : b3) p *= 3.0f;
    auto e1 = get(compareImages(view(a, 10, 10), view(b, 10, 10)));
    auto e3 = get(compareImages(view(a3, 10, 10), view(b3, 10, 10)));
    EXPECT_NEAR(e3.mae, 3.0 * e1.mae, 1e-6 * e1.mae);
    EXPECT_NEAR(e3.mse, 9.0 * e1.mse, 1e-6 * e1.mse);
}

TEST(ImageMetrics, RmaeOfAKnownRelativeError) {
    // 50 % too bright everywhere against a reference of 1: |1.5 - 1| / (1 + 0.01).
    std::vector<glm::vec4> ref(12, glm::vec4(1.0f)), img(12, glm::vec4(1.5f));
    EXPECT_NEAR(get(relativeMeanAbsoluteError(view(img, 4, 3), view(ref, 4, 3))), 0.5 / 1.01,
                1e-12);
    // A bright reference pixel forgives the same absolute error a dark one does not.
    std::vector<glm::vec4> bright(1, glm::vec4(100.0f)), brightOff(1, glm::vec4(101.0f));
    std::vector<glm::vec4> dark(1, glm::vec4(0.125f)), darkOff(1, glm::vec4(1.125f));
    double rb = get(relativeMeanAbsoluteError(view(brightOff, 1, 1), view(bright, 1, 1)));
    double rd = get(relativeMeanAbsoluteError(view(darkOff, 1, 1), view(dark, 1, 1)));
    EXPECT_NEAR(rb, 1.0 / 100.01, 1e-12);
    EXPECT_NEAR(rd, 1.0 / 0.135, 1e-9);
    EXPECT_DOUBLE_EQ(get(meanAbsoluteError(view(brightOff, 1, 1), view(bright, 1, 1))),
                     get(meanAbsoluteError(view(darkOff, 1, 1), view(dark, 1, 1))));
}

TEST(ImageMetrics, PerPixelErrorAveragesToTheMetric) {
    auto a = noiseImage(32 * 8, 6), b = noiseImage(32 * 8, 7);
    auto e = get(compareImages(view(a, 32, 8), view(b, 32, 8)));
    auto mean = [](const std::vector<float>& v) {
        double s = 0.0;
        for (float x : v) s += x;
        return s / double(v.size());
    };
    auto abs = perPixelError(view(a, 32, 8), view(b, 32, 8), PixelErrorKind::Absolute);
    auto sq = perPixelError(view(a, 32, 8), view(b, 32, 8), PixelErrorKind::Squared);
    auto rel = perPixelError(view(a, 32, 8), view(b, 32, 8), PixelErrorKind::Relative);
    ASSERT_TRUE(abs.ok() && sq.ok() && rel.ok());
    ASSERT_EQ(abs->size(), 32u * 8u);
    EXPECT_NEAR(mean(*abs), e.mae, 1e-6 * e.mae);
    EXPECT_NEAR(mean(*sq), e.mse, 1e-6 * e.mse);
    EXPECT_NEAR(mean(*rel), e.rmae, 1e-6 * e.rmae);
}

TEST(ImageMetrics, SizeMismatchIsAnError) {
    std::vector<glm::vec4> a(6), b(6), c(5);
    auto e = compareImages(view(a, 3, 2), view(b, 2, 3));
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().message, "image is 3x2 but the reference is 2x3");
    auto p = perPixelError(view(a, 3, 2), view(b, 6, 1), PixelErrorKind::Absolute);
    EXPECT_FALSE(p.ok());
    auto short_ = compareImages(view(a, 3, 2), view(c, 3, 2));
    ASSERT_FALSE(short_.ok());
    EXPECT_EQ(short_.error().message, "reference holds 5 pixels, not 3x2");
    std::vector<glm::vec4> none;
    EXPECT_FALSE(compareImages(view(none, 0, 0), view(none, 0, 0)).ok());
    EXPECT_FALSE(meanSquaredError(view(a, 3, 2), view(b, 1, 6)).ok());
}

TEST(ImageMetrics, NonFinitePixelsAreCountedAndPropagate) {
    std::vector<glm::vec4> a(4, glm::vec4(1.0f)), b(4, glm::vec4(1.0f));
    a[2].y = std::numeric_limits<float>::quiet_NaN();
    b[3].z = std::numeric_limits<float>::infinity();
    auto e = get(compareImages(view(a, 2, 2), view(b, 2, 2)));
    EXPECT_EQ(e.nonFinitePixels, 2u);
    EXPECT_TRUE(std::isnan(e.mae));
}
