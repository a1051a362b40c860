#include "metrics/display_error.h"

#include <gtest/gtest.h>
#include <vector>

using namespace engine::metrics;

namespace {

constexpr std::uint32_t kW = 32, kH = 20;

// A ramp from dark to bright along x, a little colour along y.
std::vector<glm::vec4> ramp(float scale = 1.0f) {
    std::vector<glm::vec4> v;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const float t = 0.05f + float(x) / kW;
            v.emplace_back(scale * t, scale * t * 0.9f, scale * (t + 0.01f * y), 1.0f);
        }
    return v;
}

}  // namespace

TEST(DisplayError, TheReferenceItselfHasNoError) {
    const auto ref = ramp();
    const DisplayErrors e = compareDisplay({ref, kW, kH}, {ref, kW, kH}).value();
    EXPECT_EQ(e.relativeMae, 0.0);
    EXPECT_EQ(e.relativeRmse, 0.0);
    EXPECT_NEAR(e.ssim, 1.0, 1e-12);
    EXPECT_NEAR(e.meanRatio, 1.0, 1e-12);
}

// 10 % too dark everywhere: relative MAE ~0.1 (the clamped top 2 % of the reference differ a
// little less), mean ratio 0.9 exactly.
TEST(DisplayError, ADarkImageReadsAsItsShortfall) {
    const auto ref = ramp(), dark = ramp(0.9f);
    const DisplayErrors e = compareDisplay({dark, kW, kH}, {ref, kW, kH}).value();
    EXPECT_NEAR(e.relativeMae, 0.1, 0.005);
    EXPECT_NEAR(e.meanRatio, 0.9, 1e-6);
    EXPECT_LT(e.ssim, 1.0);
}

// One firefly a thousand times the brightest pixel costs no more than one pixel at the clamp.
TEST(DisplayError, AFireflyIsClampedToTheReferencesBrightLevel) {
    const auto ref = ramp();
    auto firefly = ref;
    firefly[kW * 10 + 3] = glm::vec4(1000.0f);
    const DisplayErrors e = compareDisplay({firefly, kW, kH}, {ref, kW, kH}).value();
    EXPECT_LT(e.relativeMae, 2.0 / double(kW * kH));
    EXPECT_GT(e.meanRatio, 2.0);  // the unclamped energy still shows it
}

TEST(DisplayError, NearestUpscaleRepeatsEachPixel) {
    const std::vector<glm::vec4> src{glm::vec4(1), glm::vec4(2), glm::vec4(3), glm::vec4(4)};
    const auto up = upscaleNearest({src, 2, 2}, 4, 4);
    ASSERT_EQ(up.size(), 16u);
    EXPECT_EQ(up[0].x, 1.0f);
    EXPECT_EQ(up[1].x, 1.0f);
    EXPECT_EQ(up[2].x, 2.0f);
    EXPECT_EQ(up[4 * 2 + 0].x, 3.0f);
    EXPECT_EQ(up[4 * 3 + 3].x, 4.0f);
}

TEST(DisplayError, DifferentSizesAreAnError) {
    const auto ref = ramp();
    const std::vector<glm::vec4> small(16, glm::vec4(1));
    EXPECT_FALSE(compareDisplay({small, 4, 4}, {ref, kW, kH}));
}
