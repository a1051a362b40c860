// gpu::ComputePipeline: one compute shader (embedded SPIR-V, by name) whose bindings are all
// storage buffers in set 0, numbered 0..bindingCount-1.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

namespace engine::gpu {

class Buffer;
class CommandList;
class Context;

class ComputePipeline {
public:
    // `shader` is the path under shaders/ without ".comp", e.g. "world/primary_rays".
    ComputePipeline(Context& ctx, const std::string& shader, std::uint32_t bindingCount);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    // Binds `buffers` to bindings 0..n-1 and dispatches `groups` workgroups.
    void dispatch(CommandList& cmd, std::initializer_list<const Buffer*> buffers, std::uint32_t groupsX,
                  std::uint32_t groupsY = 1, std::uint32_t groupsZ = 1) {
        dispatch(cmd, std::span<const Buffer* const>(buffers.begin(), buffers.size()), groupsX, groupsY, groupsZ);
    }
    void dispatch(CommandList& cmd, std::span<const Buffer* const> buffers, std::uint32_t groupsX,
                  std::uint32_t groupsY = 1, std::uint32_t groupsZ = 1);

private:
    Context& mCtx;
    std::string mName;
    std::uint32_t mBindingCount;
    VkDescriptorSetLayout mSetLayout = VK_NULL_HANDLE;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
    VkDescriptorPool mPool = VK_NULL_HANDLE;
};

}  // namespace engine::gpu
