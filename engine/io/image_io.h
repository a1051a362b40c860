// Image files: PNG (stb_image_write) for tonemapped frames, EXR (OpenEXR, 32-bit float RGBA) for
// linear radiance. Both write through core/atomic_file.h: the previous file survives any failure.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "core/error.h"

namespace engine::io {

Status writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                std::span<const std::uint32_t> rgba8);
Status writeExr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                std::span<const glm::vec4> linear);

// An 8-bit RGBA image, R in the low byte (the renderer's LDR layout).
struct PngImage {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint32_t> rgba8;
};
Result<PngImage> readPng(const std::filesystem::path& path);

struct ExrImage {
    std::uint32_t width = 0, height = 0;
    std::vector<glm::vec4> pixels;
};
Result<ExrImage> readExr(const std::filesystem::path& path);

}  // namespace engine::io
