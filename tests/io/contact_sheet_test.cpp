#include "io/contact_sheet.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace engine::io;

namespace {

std::uint32_t rgba(std::uint32_t r, std::uint32_t g, std::uint32_t b, std::uint32_t a = 255) {
    return r | (g << 8) | (b << 16) | (a << 24);
}
std::uint32_t channel(std::uint32_t p, int c) { return (p >> (8 * c)) & 0xFFu; }

}  // namespace

TEST(ResizeRgba8, FlatImageStaysFlat) {
    std::vector<std::uint32_t> src(37 * 23, rgba(200, 100, 7));
    for (std::uint32_t p : resizeRgba8(src, 37, 23, 10, 6)) EXPECT_EQ(p, rgba(200, 100, 7));
}

// Averaging happens in linear light: black and white average to sRGB 188, not 128.
TEST(ResizeRgba8, AveragesInLinearLight) {
    std::vector<std::uint32_t> src = {rgba(0, 0, 0), rgba(255, 255, 255), rgba(255, 255, 255),
                                      rgba(0, 0, 0)};
    std::vector<std::uint32_t> out = resizeRgba8(src, 2, 2, 1, 1);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(channel(out[0], 0), 188u);
    EXPECT_EQ(channel(out[0], 3), 255u);
}

// Non-integer ratios weight source pixels by coverage: 3 -> 2 gives (a + b/2) and (b/2 + c).
TEST(ResizeRgba8, WeightsByCoverage) {
    std::vector<std::uint32_t> src = {rgba(255, 255, 255), rgba(0, 0, 0), rgba(0, 0, 0)};
    std::vector<std::uint32_t> out = resizeRgba8(src, 3, 1, 2, 1);
    // 2/3 white in linear light -> sRGB 1.055 * (2/3)^(1/2.4) - 0.055 = 0.836 -> 213; the right
    // pixel is black.
    EXPECT_EQ(channel(out[0], 1), 213u);
    EXPECT_EQ(channel(out[1], 1), 0u);
}

// A one-pixel bright line survives as a dimmer line instead of vanishing between samples.
TEST(ResizeRgba8, ThinLinesSurvive) {
    std::vector<std::uint32_t> src(64 * 8, rgba(0, 0, 0));
    for (int y = 0; y < 8; ++y) src[std::size_t(y) * 64 + 33] = rgba(255, 255, 255);
    std::vector<std::uint32_t> out = resizeRgba8(src, 64, 8, 8, 1);
    EXPECT_GT(channel(out[4], 0), 60u);  // the column holding x = 33
    EXPECT_EQ(channel(out[3], 0), 0u);
}

TEST(ContactSheet, PlacesThumbnailsRowMajorWithGaps) {
    ContactSheet sheet(5, 3, 4, 2, 1);
    EXPECT_EQ(sheet.width(), 3u * 4 + 4);
    EXPECT_EQ(sheet.height(), 2u * 2 + 3);
    std::vector<std::uint32_t> red(8 * 4, rgba(255, 0, 0));
    sheet.place(4, red, 8, 4);  // second row, second column
    const auto& px = sheet.pixels();
    auto at = [&](std::uint32_t x, std::uint32_t y) {
        return px[std::size_t(y) * sheet.width() + x];
    };
    EXPECT_EQ(at(1 + 1 * 5, 1 + 1 * 3), rgba(255, 0, 0));
    EXPECT_EQ(at(4 + 1 * 5, 2 + 1 * 3), rgba(255, 0, 0));
    EXPECT_NE(at(1, 1), rgba(255, 0, 0));                  // slot 0 is still empty
    EXPECT_NE(at(0 + 1 * 5, 1 + 1 * 3), rgba(255, 0, 0));  // the gap
}
