// SPIR-V of the compute shaders, embedded at build time (shaders/CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace engine::gpu {

// Empty span for an unknown name.
std::span<const std::uint32_t> shaderCode(std::string_view name);

}  // namespace engine::gpu
