#include "metrics/ssim.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using engine::metrics::ssim;

namespace {

constexpr std::uint32_t kW = 24, kH = 17;

std::vector<float> pattern() {
    std::vector<float> v;
    for (std::uint32_t j = 0; j < kH; ++j)
        for (std::uint32_t i = 0; i < kW; ++i) v.push_back(float((i * 7 + j * 13) % 11) / 10.0f);
    return v;
}

}  // namespace

TEST(Ssim, IdenticalImagesScoreOne) {
    const auto x = pattern();
    EXPECT_NEAR(ssim(x, x, kW, kH, 1.0).value(), 1.0, 1e-12);
}

// Values from scikit-image 0.19.3 (structural_similarity(x, y, data_range=L,
// gaussian_weights=True, sigma=1.5, use_sample_covariance=False)) on the same images — an
// implementation that is not ours.
TEST(Ssim, AgreesWithScikitImage) {
    const auto x = pattern();
    std::vector<float> y, z;
    for (std::uint32_t j = 0; j < kH; ++j)
        for (std::uint32_t i = 0; i < kW; ++i) {
            const float v = x[j * kW + i];
            y.push_back(float(0.8 * v + 0.1 * std::sin(i * 0.7) * std::cos(j * 0.3)));
            z.push_back(v * 0.5f + 0.25f);
        }
    EXPECT_NEAR(ssim(x, y, kW, kH, 1.0).value(), 0.9423110863396347, 1e-6);
    EXPECT_NEAR(ssim(x, z, kW, kH, 2.0).value(), 0.8055543957631358, 1e-6);
}

TEST(Ssim, RefusesImagesSmallerThanTheWindow) {
    const std::vector<float> small(10 * 10, 0.5f);
    auto r = ssim(small, small, 10, 10, 1.0);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("smaller than the 11x11 window"), std::string::npos);
}
