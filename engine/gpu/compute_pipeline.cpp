#include "gpu/compute_pipeline.h"

#include <algorithm>
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

// The SpecId decorations of a SPIR-V module (OpDecorate <id> SpecId <constant_id>), ascending.
std::vector<std::uint32_t> declaredSpecIds(std::span<const std::uint32_t> code) {
    constexpr std::uint32_t kOpDecorate = 71, kDecorationSpecId = 1, kHeaderWords = 5;
    std::vector<std::uint32_t> ids;
    for (std::size_t i = kHeaderWords; i < code.size();) {
        const std::uint32_t words = code[i] >> 16, opcode = code[i] & 0xFFFFu;
        if (words == 0 || i + words > code.size()) break;
        if (opcode == kOpDecorate && words >= 4 && code[i + 2] == kDecorationSpecId) ids.push_back(code[i + 3]);
        i += words;
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}
}  // namespace

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
    VK_CHECK(vkCreateShaderModule(device, &moduleInfo, nullptr, &mModule));
    mSpecIds = declaredSpecIds(code);
    variant({});  // the generic pipeline now: a shader that does not compile fails at start-up

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
    for (auto& [values, pipeline] : mVariants) vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyShaderModule(device, mModule, nullptr);
    vkDestroyPipelineLayout(device, mLayout, nullptr);
    vkDestroyDescriptorSetLayout(device, mSetLayout, nullptr);
}

VkPipeline ComputePipeline::variant(std::span<const std::uint32_t> specialization) {
    // Only the constants this shader declares select its variant; the others leave it alone.
    std::vector<std::uint32_t> values;
    std::vector<VkSpecializationMapEntry> entries;
    for (std::uint32_t id : mSpecIds) {
        if (id >= specialization.size()) continue;  // keeps its default
        entries.push_back({id, static_cast<std::uint32_t>(values.size() * sizeof(std::uint32_t)), sizeof(std::uint32_t)});
        values.push_back(specialization[id]);
    }
    for (auto& [key, pipeline] : mVariants) {
        if (key == values) return pipeline;
    }
    VkSpecializationInfo spec{};
    spec.mapEntryCount = static_cast<std::uint32_t>(entries.size());
    spec.pMapEntries = entries.data();
    spec.dataSize = values.size() * sizeof(std::uint32_t);
    spec.pData = values.data();
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = mModule;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = entries.empty() ? nullptr : &spec;
    info.layout = mLayout;
    VkPipeline pipeline;
    VK_CHECK(vkCreateComputePipelines(mCtx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    mCtx.setObjectName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(pipeline), mName.c_str());
    mVariants.emplace_back(std::move(values), pipeline);
    return pipeline;
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
    vkCmdBindPipeline(cmd.handle(), VK_PIPELINE_BIND_POINT_COMPUTE, variant(cmd.specialization()));
    vkCmdBindDescriptorSets(cmd.handle(), VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, 0, 1, &set, 0, nullptr);
    vkCmdDispatch(cmd.handle(), groupsX, groupsY, groupsZ);
}

}  // namespace engine::gpu
