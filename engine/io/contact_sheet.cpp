#include "io/contact_sheet.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/check.h"

namespace engine::io {

namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::uint32_t linearToSrgb8(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    float s = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint32_t>(std::lround(s * 255.0f));
}

const std::array<float, 256>& decodeTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = srgbToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

// For each output index along one axis, the source indices it covers and their weights (the
// overlap of [i, i+1) * src/dst with each source pixel), normalised to sum to 1.
struct Tap {
    std::uint32_t index;
    float weight;
};
std::vector<std::vector<Tap>> coverage(std::uint32_t src, std::uint32_t dst) {
    std::vector<std::vector<Tap>> taps(dst);
    double scale = double(src) / double(dst);
    for (std::uint32_t o = 0; o < dst; ++o) {
        double a = o * scale, b = (o + 1) * scale;
        if (scale < 1.0) {  // upscaling: the one source pixel under the output pixel's centre
            taps[o].push_back(
                {std::min(src - 1, static_cast<std::uint32_t>((o + 0.5) * scale)), 1.0f});
            continue;
        }
        for (auto i = static_cast<std::uint32_t>(std::floor(a)); i < src && i < b; ++i) {
            double overlap = std::min(b, double(i + 1)) - std::max(a, double(i));
            if (overlap > 0.0) taps[o].push_back({i, static_cast<float>(overlap / scale)});
        }
    }
    return taps;
}

}  // namespace

std::vector<std::uint32_t> resizeRgba8(std::span<const std::uint32_t> src, std::uint32_t srcWidth,
                                       std::uint32_t srcHeight, std::uint32_t dstWidth,
                                       std::uint32_t dstHeight) {
    CHECK(src.size() == std::size_t(srcWidth) * srcHeight && srcWidth > 0 && srcHeight > 0);
    CHECK(dstWidth > 0 && dstHeight > 0);
    const auto& decode = decodeTable();
    auto xs = coverage(srcWidth, dstWidth);
    auto ys = coverage(srcHeight, dstHeight);

    // Separable: rows first into linear floats, then columns.
    std::vector<std::array<float, 4>> rows(std::size_t(dstWidth) * srcHeight);
    for (std::uint32_t y = 0; y < srcHeight; ++y) {
        for (std::uint32_t x = 0; x < dstWidth; ++x) {
            std::array<float, 4> sum{};
            for (const Tap& t : xs[x]) {
                std::uint32_t p = src[std::size_t(y) * srcWidth + t.index];
                for (int c = 0; c < 3; ++c)
                    sum[std::size_t(c)] += t.weight * decode[(p >> (8 * c)) & 0xFFu];
                sum[3] += t.weight * float(p >> 24) / 255.0f;
            }
            rows[std::size_t(y) * dstWidth + x] = sum;
        }
    }
    std::vector<std::uint32_t> out(std::size_t(dstWidth) * dstHeight);
    for (std::uint32_t y = 0; y < dstHeight; ++y) {
        for (std::uint32_t x = 0; x < dstWidth; ++x) {
            std::array<float, 4> sum{};
            for (const Tap& t : ys[y]) {
                const auto& r = rows[std::size_t(t.index) * dstWidth + x];
                for (int c = 0; c < 4; ++c) sum[std::size_t(c)] += t.weight * r[std::size_t(c)];
            }
            std::uint32_t a =
                static_cast<std::uint32_t>(std::lround(std::clamp(sum[3], 0.0f, 1.0f) * 255.0f));
            out[std::size_t(y) * dstWidth + x] = linearToSrgb8(sum[0]) |
                                                 (linearToSrgb8(sum[1]) << 8) |
                                                 (linearToSrgb8(sum[2]) << 16) | (a << 24);
        }
    }
    return out;
}

ContactSheet::ContactSheet(std::uint32_t count, std::uint32_t columns, std::uint32_t thumbWidth,
                           std::uint32_t thumbHeight, std::uint32_t gap)
    : mCount(count),
      mColumns(std::max(1u, std::min(columns, count))),
      mThumbWidth(thumbWidth),
      mThumbHeight(thumbHeight),
      mGap(gap) {
    CHECK(count > 0 && thumbWidth > 0 && thumbHeight > 0);
    std::uint32_t rows = (mCount + mColumns - 1) / mColumns;
    mWidth = mColumns * mThumbWidth + (mColumns + 1) * mGap;
    mHeight = rows * mThumbHeight + (rows + 1) * mGap;
    mPixels.assign(std::size_t(mWidth) * mHeight,
                   0xFF202020u);  // opaque dark grey between thumbnails
}

void ContactSheet::place(std::uint32_t slot, std::span<const std::uint32_t> rgba8,
                         std::uint32_t width, std::uint32_t height) {
    CHECK(slot < mCount);
    std::vector<std::uint32_t> thumb = resizeRgba8(rgba8, width, height, mThumbWidth, mThumbHeight);
    std::uint32_t x0 = mGap + (slot % mColumns) * (mThumbWidth + mGap);
    std::uint32_t y0 = mGap + (slot / mColumns) * (mThumbHeight + mGap);
    for (std::uint32_t y = 0; y < mThumbHeight; ++y)
        std::copy_n(thumb.begin() + std::ptrdiff_t(y) * mThumbWidth, mThumbWidth,
                    mPixels.begin() + std::ptrdiff_t(y0 + y) * mWidth + x0);
}

}  // namespace engine::io
