#include "metrics/heat_map.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

using namespace engine::metrics;

namespace {

float luminance(glm::vec3 srgb) {
    glm::vec3 lin = glm::pow(srgb, glm::vec3(2.2f));
    return glm::dot(lin, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

glm::uvec2 pngSize(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char header[24] = {};
    in.read(reinterpret_cast<char*>(header), sizeof(header));
    EXPECT_EQ(std::string(reinterpret_cast<char*>(header) + 1, 3), "PNG");
    auto be32 = [&](int at) {
        return std::uint32_t(header[at]) << 24 | std::uint32_t(header[at + 1]) << 16 |
               std::uint32_t(header[at + 2]) << 8 | header[at + 3];
    };
    return {be32(16), be32(20)};  // IHDR width and height
}

}  // namespace

TEST(HeatMap, RampIsPerceptuallyOrdered) {
    float previous = -1.0f;
    for (int i = 0; i <= 100; ++i) {
        float l = luminance(heatRamp(float(i) / 100.0f));
        EXPECT_GT(l, previous) << "t = " << i / 100.0;
        previous = l;
    }
    EXPECT_LT(luminance(heatRamp(0.0f)), 0.01f);
    EXPECT_GT(luminance(heatRamp(1.0f)), 0.8f);
    EXPECT_EQ(heatRamp(-3.0f), heatRamp(0.0f));
    EXPECT_EQ(heatRamp(7.0f), heatRamp(1.0f));
}

TEST(HeatMap, MapsZeroToTheBottomAndTheMaxToTheTop) {
    std::vector<float> values = {0.0f, 0.5f, 1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN(),
                                 0.25f};
    auto map = makeHeatMap(values, 3, 2, HeatMapOptions{1.0f, false});
    ASSERT_TRUE(map.ok()) << map.error().message;
    EXPECT_EQ(map->width, 3u);
    EXPECT_EQ(map->height, 2u);
    EXPECT_EQ(map->maxValue, 1.0f);
    EXPECT_EQ(map->rgba8[0] & 0xFFFFFFu, 0x050000u) << "heatRamp(0) = (0, 0, 0.02)";
    EXPECT_EQ(map->rgba8[2], map->rgba8[3]) << "errors above the max clamp to the top colour";
    EXPECT_NE(map->rgba8[1], map->rgba8[2]);
    EXPECT_EQ(map->rgba8[4], kHeatMapNonFinite);
}

TEST(HeatMap, AutomaticRangeIgnoresFireflies) {
    std::vector<float> values(1000);
    for (int i = 0; i < 1000; ++i) values[i] = float(i) * 0.001f;
    values[17] = 1.0e6f;  // a firefly
    values[18] = std::numeric_limits<float>::infinity();
    float max = heatMapAutoMax(values);
    EXPECT_GT(max, 0.95f);
    EXPECT_LT(max, 1.0f);
    std::vector<float> zeros(16, 0.0f);
    EXPECT_GT(heatMapAutoMax(zeros), 0.0f);
    auto map = makeHeatMap(zeros, 4, 4, HeatMapOptions{0.0f, false});
    ASSERT_TRUE(map.ok());
    EXPECT_EQ(map->rgba8[5], map->rgba8[0]);
}

TEST(HeatMap, WritesAPngOfTheImageSizePlusTheLegend) {
    const std::uint32_t w = 96, h = 40;
    std::vector<float> values(w * h);
    for (std::uint32_t i = 0; i < values.size(); ++i) values[i] = float(i % w) / float(w);
    auto path = std::filesystem::temp_directory_path() / "vox_heat_map_test.png";
    std::filesystem::remove(path);
    auto map = writeHeatMap(path, values, w, h);
    ASSERT_TRUE(map.ok()) << map.error().message;
    std::uint32_t legend = heatMapLegendHeight(w);
    EXPECT_GT(legend, 0u);
    EXPECT_EQ(map->height, h + legend);
    EXPECT_EQ(pngSize(path), glm::uvec2(w, h + legend));
    // The legend's ramp runs from the bottom colour to the top colour.
    std::size_t ramp = std::size_t(h + 3) * w;
    EXPECT_NE(map->rgba8[ramp], map->rgba8[ramp + w - 1]);
    // Labels are drawn in white into the strip.
    int white = 0;
    for (std::size_t i = std::size_t(h) * w; i < map->rgba8.size(); ++i)
        white += map->rgba8[i] == 0xFFFFFFFFu;
    EXPECT_GT(white, 10);
    std::filesystem::remove(path);

    auto narrow = makeHeatMap(std::vector<float>(8, 0.0f), 8, 1);
    ASSERT_TRUE(narrow.ok());
    EXPECT_EQ(narrow->height, 1u) << "no legend where it does not fit";
}

TEST(HeatMap, RejectsBadInput) {
    std::vector<float> values(10);
    EXPECT_FALSE(makeHeatMap(values, 3, 3).ok());
    EXPECT_FALSE(makeHeatMap(values, 10, 1, HeatMapOptions{-1.0f, true}).ok());
    auto bad = writeHeatMap("/nonexistent-dir/x.png", values, 10, 1);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("/nonexistent-dir/x.png"), std::string::npos)
        << bad.error().message;
}
