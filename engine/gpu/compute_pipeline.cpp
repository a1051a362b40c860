#include "gpu/compute_pipeline.h"

#include <vector>

#include "core/check.h"
#include "gpu/buffer.h"
#include "gpu/command_list.h"
#include "gpu/context.h"
#include "gpu/shader_registry.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

namespace {
constexpr std::uint32_t kSetsPerPool = 64;  // dispatches of one pipeline in flight at once
}

ComputePipeline::ComputePipeline(Context& ctx, const std::string& shader, std::uint32_t bindingCount)
    : mCtx(ctx), mName(shader), mBindingCount(bindingCount) {
    std::span<const std::uint32_t> code = shaderCode(shader);
    CHECK_MSG(!code.empty(), "no embedded shader named '%s'", shader.c_str());
    VkDevice device = ctx.device();

    std::vector<VkDescriptorSetLayoutBinding> bindings(bindingCount);
    for (std::uint32_t i = 0; i < bindingCount; ++i) {
        bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = bindingCount;
    setInfo.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &mSetLayout));

    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &mSetLayout;
    VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &mLayout));

    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = code.size_bytes();
    moduleInfo.pCode = code.data();
    VkShaderModule module;
    VK_CHECK(vkCreateShaderModule(device, &moduleInfo, nullptr, &module));

    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.layout = mLayout;
    VK_CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &mPipeline));
    vkDestroyShaderModule(device, module, nullptr);
    ctx.setObjectName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(mPipeline), shader.c_str());

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, bindingCount * kSetsPerPool};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = kSetsPerPool;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &mPool));
}

ComputePipeline::~ComputePipeline() {
    VkDevice device = mCtx.device();
    vkDestroyDescriptorPool(device, mPool, nullptr);
    vkDestroyPipeline(device, mPipeline, nullptr);
    vkDestroyPipelineLayout(device, mLayout, nullptr);
    vkDestroyDescriptorSetLayout(device, mSetLayout, nullptr);
}

void ComputePipeline::dispatch(CommandList& cmd, std::span<const Buffer* const> buffers, std::uint32_t groupsX,
                               std::uint32_t groupsY, std::uint32_t groupsZ) {
    CHECK_MSG(buffers.size() == mBindingCount, "%s: %zu buffers for %u bindings", mName.c_str(), buffers.size(),
              mBindingCount);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = mPool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &mSetLayout;
    VkDescriptorSet set;
    VK_CHECK(vkAllocateDescriptorSets(mCtx.device(), &alloc, &set));
    cmd.retainDescriptorSet(mPool, set);

    std::vector<VkDescriptorBufferInfo> infos;
    std::vector<VkWriteDescriptorSet> writes;
    infos.reserve(buffers.size());
    std::uint32_t binding = 0;
    for (const Buffer* b : buffers) {
        CHECK_MSG(b && b->valid(), "%s: binding %u has no buffer", mName.c_str(), binding);
        infos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = binding++;
        w.descriptorCount = 1;
        w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w.pBufferInfo = &infos.back();
        writes.push_back(w);
    }
    vkUpdateDescriptorSets(mCtx.device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
    vkCmdBindPipeline(cmd.handle(), VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline);
    vkCmdBindDescriptorSets(cmd.handle(), VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, 0, 1, &set, 0, nullptr);
    vkCmdDispatch(cmd.handle(), groupsX, groupsY, groupsZ);
}

}  // namespace engine::gpu
