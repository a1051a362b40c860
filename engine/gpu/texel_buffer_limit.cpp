#include "gpu/texel_buffer_limit.h"

#include <fmt/format.h>

#include "gpu/context.h"

namespace engine::gpu {

void checkTexelCount(const Context& ctx, std::uint64_t texels, const std::string& what) {
    const std::uint64_t limit = ctx.info().maxTexelBufferElements;
    if (texels <= limit) return;
    throw TexelBufferTooLarge(fmt::format(
        "{} too large for the GPU's texel buffer: {} texels, limit {} (maxTexelBufferElements)",
        what, texels, limit));
}

}  // namespace engine::gpu
