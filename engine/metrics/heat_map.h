// Error heat maps: per-pixel errors (metrics/image_metrics.h perPixelError) mapped through a
// perceptually ordered colour ramp and written as PNG, with a legend strip underneath that shows
// the ramp and its range ("0" at the left end, the top value at the right end).
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "core/error.h"

namespace engine::metrics {

// An inferno-like ramp (black - purple - red - orange - pale yellow) as 11 sRGB control points
// placed by hand along matplotlib's "inferno", linearly interpolated: luminance rises
// monotonically, so brighter always means a larger error, also in greyscale.
// t is clamped to [0, 1]; returns sRGB in [0, 1].
glm::vec3 heatRamp(float t);

// Drawn for pixels whose error is NaN or infinite: a green that the ramp never produces.
inline constexpr std::uint32_t kHeatMapNonFinite = 0xFF00FF00u;

struct HeatMapOptions {
    // Error mapped to the top of the ramp; larger errors clamp to it. 0 = automatic: the 99th
    // percentile of the finite errors, so that a few fireflies do not wash out the map.
    float maxValue = 0.0f;
    bool legend = true;
};

struct HeatMap {
    std::uint32_t width = 0;
    std::uint32_t height = 0;          // image height plus the legend strip
    float maxValue = 0.0f;             // the range actually used: 0 .. maxValue
    std::vector<std::uint32_t> rgba8;  // R in the low byte, as io::writePng takes it
};

// Height of the legend strip under an image of this width (0 when it would not fit).
std::uint32_t heatMapLegendHeight(std::uint32_t width);
// The automatic maxValue: 99th percentile of the finite values (a tiny positive value when
// they are all zero, so the map stays black instead of dividing by zero).
float heatMapAutoMax(std::span<const float> values);

Result<HeatMap> makeHeatMap(std::span<const float> values, std::uint32_t width,
                            std::uint32_t height, const HeatMapOptions& options = {});
Result<HeatMap> writeHeatMap(const std::filesystem::path& path, std::span<const float> values,
                             std::uint32_t width, std::uint32_t height,
                             const HeatMapOptions& options = {});

}  // namespace engine::metrics
