// Contact sheets: frames of a capture as a grid of thumbnails in one image, to see a whole
// flythrough at a glance. Thumbnails are area-averaged in linear light (each output pixel the
// exact coverage-weighted mean of the source pixels under it), so thin bright features neither
// vanish nor alias the way point sampling would make them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace engine::io {

// Downscales (or upscales) an RGBA8 sRGB image, R in the low byte, by area averaging in linear
// light; alpha is averaged as is.
std::vector<std::uint32_t> resizeRgba8(std::span<const std::uint32_t> src, std::uint32_t srcWidth,
                                       std::uint32_t srcHeight, std::uint32_t dstWidth,
                                       std::uint32_t dstHeight);

class ContactSheet {
public:
    // `count` thumbnails of thumbWidth x thumbHeight in rows of `columns`, `gap` pixels apart.
    ContactSheet(std::uint32_t count, std::uint32_t columns, std::uint32_t thumbWidth,
                 std::uint32_t thumbHeight, std::uint32_t gap = 2);

    // Puts a frame, scaled to the thumbnail size, in slot `slot` (row-major).
    void place(std::uint32_t slot, std::span<const std::uint32_t> rgba8, std::uint32_t width,
               std::uint32_t height);

    std::uint32_t width() const { return mWidth; }
    std::uint32_t height() const { return mHeight; }
    const std::vector<std::uint32_t>& pixels() const { return mPixels; }

private:
    std::uint32_t mCount, mColumns, mThumbWidth, mThumbHeight, mGap;
    std::uint32_t mWidth = 0, mHeight = 0;
    std::vector<std::uint32_t> mPixels;
};

}  // namespace engine::io
