// gpu::ComputePipeline: one compute shader (embedded SPIR-V, by name) whose bindings are buffers
// in set 0, numbered 0..bindingCount-1. Each binding's descriptor type follows the shader's
// declaration (read from the SPIR-V): a `buffer` block is a storage buffer, a `usamplerBuffer` a
// uniform texel buffer (bound through the Buffer's texel view, Buffer::setTexelFormat). Its
// specialization constants take their values from the command list's
// (CommandList::setSpecialization, indexed by constant_id); one pipeline is compiled per
// combination of the values the shader declares, when first used.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <utility>
#include <vector>
#include <vulkan/vulkan.h>

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

    // Binds `buffers` to bindings 0..n-1 and dispatches `groups` workgroups. The list orders the
    // dispatch after what it depends on (CommandList::access) by `declaredWrites` — which buffers
    // the caller declares written (a pass's Io struct; it must cover every binding the shader may
    // write) — or, without it, by the shader's own declarations (`readonly`).
    void dispatch(CommandList& cmd, std::initializer_list<const Buffer*> buffers,
                  std::uint32_t groupsX, std::uint32_t groupsY = 1, std::uint32_t groupsZ = 1) {
        dispatch(cmd, std::span<const Buffer* const>(buffers.begin(), buffers.size()), groupsX,
                 groupsY, groupsZ);
    }
    void dispatch(CommandList& cmd, std::span<const Buffer* const> buffers, std::uint32_t groupsX,
                  std::uint32_t groupsY = 1, std::uint32_t groupsZ = 1,
                  std::span<const std::uint8_t> declaredWrites = {});
    // The same, with the workgroup counts read on the GPU from `args` at `offset` (three uints,
    // VkDispatchIndirectCommand), as an earlier pass wrote them.
    void dispatchIndirect(CommandList& cmd, std::span<const Buffer* const> buffers,
                          const Buffer& args, std::uint64_t offset,
                          std::span<const std::uint8_t> declaredWrites = {});

    // The constant_ids the shader declares, ascending.
    const std::vector<std::uint32_t>& specializationIds() const { return mSpecIds; }
    // The descriptor type of each binding, as the shader declares it.
    const std::vector<VkDescriptorType>& bindingTypes() const { return mTypes; }
    // Whether the shader may write each binding (a storage buffer not declared readonly).
    const std::vector<bool>& writableBindings() const { return mWritable; }

private:
    // Allocates, fills and binds a descriptor set of `buffers`, and binds the pipeline.
    void bind(CommandList& cmd, std::span<const Buffer* const> buffers);
    // Tells the list what the dispatch reads and writes (`args`: its indirect arguments).
    void declareAccess(CommandList& cmd, std::span<const Buffer* const> buffers,
                       std::span<const std::uint8_t> declaredWrites, const Buffer* args) const;
    // The pipeline for these values of the shader's constants (empty: every default).
    VkPipeline variant(std::span<const std::uint32_t> specialization);

    Context& mCtx;
    std::string mName;
    std::uint32_t mBindingCount;
    VkShaderModule mModule = VK_NULL_HANDLE;
    std::vector<std::uint32_t> mSpecIds;
    std::vector<VkDescriptorType> mTypes;
    std::vector<bool> mWritable;
    VkDescriptorSetLayout mSetLayout = VK_NULL_HANDLE;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    // (values of mSpecIds, pipeline); a handful at most, so a list.
    std::vector<std::pair<std::vector<std::uint32_t>, VkPipeline>> mVariants;
    VkDescriptorPool mPool = VK_NULL_HANDLE;
};

}  // namespace engine::gpu
