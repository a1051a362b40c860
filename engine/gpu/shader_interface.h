// What a compute shader's SPIR-V declares for the pipeline built on it: its specialisation
// constants and, per binding of descriptor set 0, the descriptor type and whether it may write.
// Read with SPIRV-Cross's reflection, so the pipeline's layout follows the shader's source.
#pragma once

#include <cstdint>
#include <span>
#include <vector>
#include <vulkan/vulkan.h>

namespace engine::gpu {

struct ShaderInterface {
    std::vector<std::uint32_t> specIds;  // constant_id values, ascending
    // Bindings 0..count-1 of set 0: a `uniform usamplerBuffer` is a uniform texel buffer;
    // anything else (a `buffer` block, or a binding the shader does not declare) a storage buffer.
    std::vector<VkDescriptorType> bindingTypes;
    // A storage buffer not declared `readonly` (as a whole or in every member); texel buffers and
    // bindings the shader does not declare are read-only.
    std::vector<bool> writable;
};

// `name` is for the error: a module that does not parse, or a binding of a kind the pipelines do
// not bind (a storage image, an image that is not a buffer), is a programming error (CHECK).
ShaderInterface reflectShaderInterface(std::span<const std::uint32_t> code,
                                       std::uint32_t bindingCount, const char* name);

}  // namespace engine::gpu
