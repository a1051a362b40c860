#include "gpu/compute_pipeline.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "core/check.h"
#include "gpu/buffer.h"
#include "gpu/command_list.h"
#include "gpu/context.h"
#include "gpu/shader_interface.h"
#include "gpu/shader_registry.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

namespace {
constexpr std::uint32_t kSetsPerPool = 64;  // dispatches of one pipeline in flight at once
}  // namespace

ComputePipeline::ComputePipeline(Context& ctx, const std::string& shader,
                                 std::uint32_t bindingCount)
    : mCtx(ctx), mName(shader), mBindingCount(bindingCount) {
    std::span<const std::uint32_t> code = shaderCode(shader);
    CHECK_MSG(!code.empty(), "no embedded shader named '%s'", shader.c_str());
    VkDevice device = ctx.device();

    ShaderInterface declared = reflectShaderInterface(code, bindingCount, shader.c_str());
    mTypes = std::move(declared.bindingTypes);
    mWritable = std::move(declared.writable);
    mSpecIds = std::move(declared.specIds);
    std::vector<VkDescriptorSetLayoutBinding> bindings(bindingCount);
    for (std::uint32_t i = 0; i < bindingCount; ++i) {
        bindings[i] = {i, mTypes[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
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
    variant({});  // the generic pipeline now: a shader that does not compile fails at start-up

    std::vector<VkDescriptorPoolSize> sizes;
    for (VkDescriptorType type : mTypes) {
        auto same = std::find_if(sizes.begin(), sizes.end(),
                                 [&](const VkDescriptorPoolSize& s) { return s.type == type; });
        if (same == sizes.end()) same = sizes.insert(sizes.end(), {type, 0});
        same->descriptorCount += kSetsPerPool;
    }
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = kSetsPerPool;
    poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
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
        entries.push_back({id, static_cast<std::uint32_t>(values.size() * sizeof(std::uint32_t)),
                           sizeof(std::uint32_t)});
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
    mCtx.setObjectName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(pipeline),
                       mName.c_str());
    mVariants.emplace_back(std::move(values), pipeline);
    return pipeline;
}

void ComputePipeline::dispatch(CommandList& cmd, std::span<const Buffer* const> buffers,
                               std::uint32_t groupsX, std::uint32_t groupsY, std::uint32_t groupsZ,
                               std::span<const std::uint8_t> declaredWrites) {
    declareAccess(cmd, buffers, declaredWrites, nullptr);
    bind(cmd, buffers);
    vkCmdDispatch(cmd.handle(), groupsX, groupsY, groupsZ);
}

void ComputePipeline::dispatchIndirect(CommandList& cmd, std::span<const Buffer* const> buffers,
                                       const Buffer& args, std::uint64_t offset,
                                       std::span<const std::uint8_t> declaredWrites) {
    CHECK_MSG(args.valid() && offset % 4 == 0 && offset + 12 <= args.size(),
              "%s: indirect arguments at %llu of %s", mName.c_str(),
              static_cast<unsigned long long>(offset), args.name().c_str());
    declareAccess(cmd, buffers, declaredWrites, &args);
    bind(cmd, buffers);
    vkCmdDispatchIndirect(cmd.handle(), args.handle(), offset);
}

void ComputePipeline::declareAccess(CommandList& cmd, std::span<const Buffer* const> buffers,
                                    std::span<const std::uint8_t> declaredWrites,
                                    const Buffer* args) const {
    CHECK_MSG(declaredWrites.empty() || declaredWrites.size() == buffers.size(),
              "%s: %zu accesses for %zu buffers", mName.c_str(), declaredWrites.size(),
              buffers.size());
    std::vector<const Buffer*> reads, writes;
    if (args) reads.push_back(args);
    for (std::size_t b = 0; b < buffers.size(); ++b) {
        const bool shaderWrites = b < mWritable.size() && mWritable[b];
        // A declaration may say more than the shader does (one Io for several passes), never less:
        // the barriers follow it.
        CHECK_MSG(
            declaredWrites.empty() || declaredWrites[b] || !shaderWrites,
            "%s: binding %zu (%s) is declared read, but the shader may write it (not readonly)",
            mName.c_str(), b, buffers[b] ? buffers[b]->name().c_str() : "none");
        const bool written = declaredWrites.empty() ? shaderWrites : declaredWrites[b];
        if (buffers[b]) (written ? writes : reads).push_back(buffers[b]);
    }
    cmd.access(reads, writes);
}

void ComputePipeline::bind(CommandList& cmd, std::span<const Buffer* const> buffers) {
    CHECK_MSG(buffers.size() == mBindingCount, "%s: %zu buffers for %u bindings", mName.c_str(),
              buffers.size(), mBindingCount);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = mPool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &mSetLayout;
    VkDescriptorSet set;
    VK_CHECK(vkAllocateDescriptorSets(mCtx.device(), &alloc, &set));
    cmd.retainDescriptorSet(mPool, set);

    std::vector<VkDescriptorBufferInfo> infos;
    std::vector<VkBufferView> views;
    std::vector<VkWriteDescriptorSet> writes;
    infos.reserve(buffers.size());
    views.reserve(buffers.size());
    std::uint32_t binding = 0;
    for (const Buffer* b : buffers) {
        CHECK_MSG(b && b->valid(), "%s: binding %u has no buffer", mName.c_str(), binding);
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = mTypes[binding];
        if (w.descriptorType == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) {
            CHECK_MSG(b->texelView(),
                      "%s: binding %u reads texels of %s, which has no texel format", mName.c_str(),
                      binding, b->name().c_str());
            views.push_back(b->texelView());
            w.pTexelBufferView = &views.back();
        } else {
            infos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
            w.pBufferInfo = &infos.back();
        }
        writes.push_back(w);
        ++binding;
    }
    vkUpdateDescriptorSets(mCtx.device(), static_cast<std::uint32_t>(writes.size()), writes.data(),
                           0, nullptr);
    vkCmdBindPipeline(cmd.handle(), VK_PIPELINE_BIND_POINT_COMPUTE, variant(cmd.specialization()));
    vkCmdBindDescriptorSets(cmd.handle(), VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, 0, 1, &set, 0,
                            nullptr);
}

}  // namespace engine::gpu
