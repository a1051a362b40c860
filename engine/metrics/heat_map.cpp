#include "metrics/heat_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "core/bitmap_font.h"
#include "io/image_io.h"

namespace engine::metrics {

namespace {

// sRGB control points at t = 0, 0.1, ..., 1, read off matplotlib's inferno by eye and rounded.
constexpr std::array<glm::vec3, 11> kRamp = {{
    {0.00f, 0.00f, 0.02f},
    {0.09f, 0.04f, 0.22f},
    {0.26f, 0.04f, 0.41f},
    {0.42f, 0.09f, 0.43f},
    {0.58f, 0.15f, 0.40f},
    {0.74f, 0.22f, 0.33f},
    {0.87f, 0.32f, 0.23f},
    {0.95f, 0.47f, 0.10f},
    {0.99f, 0.65f, 0.04f},
    {0.96f, 0.84f, 0.27f},
    {0.99f, 1.00f, 0.64f},
}};

std::uint32_t packRgba8(glm::vec3 srgb) {
    glm::uvec3 c = glm::uvec3(glm::clamp(srgb, 0.0f, 1.0f) * 255.0f + 0.5f);
    return c.x | (c.y << 8) | (c.z << 16) | 0xFF000000u;
}

// Writes `text` with 1-pixel glyph cells at (x, y) (top-left), clipped to the image.
void drawText(std::vector<std::uint32_t>& rgba8, std::uint32_t width, std::uint32_t height, int x,
              int y, const std::string& text, std::uint32_t colour) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        int gx0 = x + int(i) * (kGlyphWidth + 1);
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int gx = 0; gx < kGlyphWidth; ++gx) {
                int px = gx0 + gx, py = y + row;
                if (px < 0 || py < 0 || px >= int(width) || py >= int(height)) continue;
                if (glyphPixel(text[i], gx, row))
                    rgba8[std::size_t(py) * width + std::size_t(px)] = colour;
            }
    }
}

int textWidth(const std::string& text) { return int(text.size()) * (kGlyphWidth + 1) - 1; }

}  // namespace

glm::vec3 heatRamp(float t) {
    if (!(t > 0.0f)) return kRamp.front();  // also catches NaN
    if (t >= 1.0f) return kRamp.back();
    float x = t * float(kRamp.size() - 1);
    auto i = static_cast<std::size_t>(x);
    return glm::mix(kRamp[i], kRamp[i + 1], x - float(i));
}

std::uint32_t heatMapLegendHeight(std::uint32_t width) {
    // A 6-pixel ramp, a gap, one line of 7-pixel text, a margin; needs room for "0" and a number.
    return width >= 48 ? 6u + 2u + std::uint32_t(kGlyphHeight) + 2u : 0u;
}

float heatMapAutoMax(std::span<const float> values) {
    std::vector<float> finite;
    finite.reserve(values.size());
    for (float v : values) {
        if (std::isfinite(v)) finite.push_back(v);
    }
    if (finite.empty()) return 1e-30f;
    auto at =
        finite.begin() + std::ptrdiff_t(std::min(finite.size() - 1, finite.size() * 99 / 100));
    std::nth_element(finite.begin(), at, finite.end());
    return std::max(*at, 1e-30f);
}

Result<HeatMap> makeHeatMap(std::span<const float> values, std::uint32_t width,
                            std::uint32_t height, const HeatMapOptions& options) {
    if (width == 0 || height == 0 || values.size() != std::size_t(width) * height)
        return makeError("heat map: {} values do not make a {}x{} image", values.size(), width,
                         height);
    if (!(options.maxValue >= 0.0f) || !std::isfinite(options.maxValue))
        return makeError("heat map: the top of the range must be a finite number >= 0, not {}",
                         options.maxValue);
    HeatMap map;
    map.width = width;
    map.maxValue = options.maxValue > 0.0f ? options.maxValue : heatMapAutoMax(values);
    std::uint32_t legend = options.legend ? heatMapLegendHeight(width) : 0u;
    map.height = height + legend;
    map.rgba8.assign(std::size_t(width) * map.height, 0xFF000000u);
    for (std::size_t i = 0; i < values.size(); ++i) {
        map.rgba8[i] = std::isfinite(values[i]) ? packRgba8(heatRamp(values[i] / map.maxValue))
                                                : kHeatMapNonFinite;
    }
    if (legend > 0) {
        std::size_t top = std::size_t(height) * width;
        for (std::uint32_t y = 1; y < 7; ++y)
            for (std::uint32_t x = 0; x < width; ++x)
                map.rgba8[top + std::size_t(y) * width + x] =
                    packRgba8(heatRamp(float(x) / float(width - 1)));
        const std::uint32_t white = 0xFFFFFFFFu;
        int textY = int(height) + 9;
        drawText(map.rgba8, width, map.height, 1, textY, "0", white);
        std::string hi = fmt::format("{:.3g}", map.maxValue);
        drawText(map.rgba8, width, map.height, int(width) - 1 - textWidth(hi), textY, hi, white);
    }
    return map;
}

Result<HeatMap> writeHeatMap(const std::filesystem::path& path, std::span<const float> values,
                             std::uint32_t width, std::uint32_t height,
                             const HeatMapOptions& options) {
    auto map = makeHeatMap(values, width, height, options);
    if (!map) return map.error();
    if (Status s = io::writePng(path, map->width, map->height, map->rgba8); !s) return s.error();
    return map;
}

}  // namespace engine::metrics
