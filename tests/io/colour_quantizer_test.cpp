#include "io/colour_quantizer.h"

#include <gtest/gtest.h>

using namespace engine::io;

TEST(ColourQuantizer, FewColoursAreKeptExactly) {
    ColourHistogram h;
    h.add({0.1f, 0.2f, 0.3f}, 10);
    h.add({0.9f, 0.8f, 0.7f}, 1);
    h.add({0.1f, 0.2f, 0.3f}, 5);
    auto palette = quantizeColours(h, 4);
    ASSERT_EQ(palette.size(), 2u);
    ColourMapper m(palette);
    EXPECT_EQ(palette[std::size_t(m.nearest({0.1f, 0.2f, 0.3f}))], glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(palette[std::size_t(m.nearest({0.9f, 0.8f, 0.7f}))], glm::vec3(0.9f, 0.8f, 0.7f));
}

TEST(ColourQuantizer, ManyColoursStayWithinTheCubeBound) {
    ColourHistogram h;
    for (int r = 0; r < 32; ++r)
        for (int g = 0; g < 32; ++g)
            for (int b = 0; b < 32; ++b) h.add(glm::vec3(r, g, b) / 31.0f);
    EXPECT_FALSE(h.binned());
    auto palette = quantizeColours(h, 64);
    ASSERT_EQ(palette.size(), 64u);
    ColourMapper m(palette);
    ColourError e;
    for (int r = 0; r < 32; ++r)
        for (int g = 0; g < 32; ++g)
            for (int b = 0; b < 32; ++b) {
                glm::vec3 c = glm::vec3(r, g, b) / 31.0f;
                e.add(glm::length(c - palette[std::size_t(m.nearest(c))]));
            }
    // 64 cells of the unit cube are 1/4 on a side: the farthest point of a cell is sqrt(3)/8 away.
    EXPECT_LE(e.max, 0.25);
    EXPECT_LE(e.mean(), 0.13);
}

TEST(ColourQuantizer, BinsBeyondTheExactLimitAndClampsAlbedo) {
    ColourHistogram h;
    for (int i = 0; i < 70000; ++i) h.add(glm::vec3(float(i) / 70000.0f, 0.5f, 2.0f));
    EXPECT_TRUE(h.binned());
    auto palette = quantizeColours(h, 8);
    EXPECT_LE(palette.size(), 8u);
    for (auto c : palette) EXPECT_LE(c.z, 1.0f) << "albedo is clamped to [0, 1]";
    EXPECT_EQ(clampAlbedo(glm::vec3(-1.0f, 0.5f, std::nanf(""))), glm::vec3(0.0f, 0.5f, 0.0f));
}
