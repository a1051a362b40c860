// The device's limit on a texel view: at most maxTexelBufferElements texels (2^27 on lavapipe).
// A view over the limit fails in the driver or validation, so every place that makes one checks
// first and refuses with TexelBufferTooLarge, whose what() is one line naming the count and the
// limit; vox prints it and exits non-zero (tools/vox/main.cpp).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace engine::gpu {

class Context;

class TexelBufferTooLarge : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws TexelBufferTooLarge ("WHAT too large for the GPU's texel buffer: N texels, limit M")
// when `texels` exceeds the context's maxTexelBufferElements.
void checkTexelCount(const Context& ctx, std::uint64_t texels, const std::string& what);

}  // namespace engine::gpu
