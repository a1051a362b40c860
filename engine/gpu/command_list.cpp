#include "gpu/command_list.h"

#include <algorithm>

#include "core/check.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/timestamp_timer.h"
#include "gpu/vk_check.h"

namespace engine::gpu {

namespace {
PFN_vkCmdBeginDebugUtilsLabelEXT gBeginLabel = nullptr;
PFN_vkCmdEndDebugUtilsLabelEXT gEndLabel = nullptr;
}  // namespace

CommandList::CommandList(Context& ctx, TimestampTimer* timer) : mCtx(ctx), mTimer(timer) {
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = ctx.commandPool();
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &info, &mCmd));
    if (ctx.debugUtils() && !gBeginLabel) {
        gBeginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetDeviceProcAddr(ctx.device(), "vkCmdBeginDebugUtilsLabelEXT"));
        gEndLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
            vkGetDeviceProcAddr(ctx.device(), "vkCmdEndDebugUtilsLabelEXT"));
    }
}

CommandList::~CommandList() {
    if (mPending) wait();
    if (mFence) vkDestroyFence(mCtx.device(), mFence, nullptr);
    vkFreeCommandBuffers(mCtx.device(), mCtx.commandPool(), 1, &mCmd);
}

void CommandList::begin() {
    CHECK(!mRecording && !mPending);
    VK_CHECK(vkResetCommandBuffer(mCmd, 0));
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(mCmd, &info));
    if (mTimer) mTimer->reset(mCmd);
    mRecording = true;
    mRead.clear();
    mWritten.clear();
}

void CommandList::finishRecording() {
    // The last commands' writes before the host reads them and before the next submission's
    // commands, which track their own accesses from none.
    if (!mRead.empty() || !mWritten.empty()) barrier();
    VK_CHECK(vkEndCommandBuffer(mCmd));
}

void CommandList::submitAndWait(const SubmitSync& sync) {
    CHECK(mRecording);
    finishRecording();
    mRecording = false;
    mCtx.submitAndWait(mCmd, sync);
    releaseSubmissionResources();
}

void CommandList::submit(const SubmitSync& sync) {
    CHECK(mRecording);
    finishRecording();
    mRecording = false;
    if (!mFence) {
        VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(mCtx.device(), &info, nullptr, &mFence));
    }
    mCtx.submit(mCmd, mFence, sync);
    mPending = true;
}

void CommandList::wait() {
    CHECK(mPending);
    VK_CHECK(vkWaitForFences(mCtx.device(), 1, &mFence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(mCtx.device(), 1, &mFence));
    mPending = false;
    mCtx.countCompleted();
    releaseSubmissionResources();
}

void CommandList::releaseSubmissionResources() {
    for (auto [pool, set] : mDescriptorSets)
        VK_CHECK(vkFreeDescriptorSets(mCtx.device(), pool, 1, &set));
    mDescriptorSets.clear();
}

void CommandList::beginPass(const std::string& name) {
    if (gBeginLabel) {
        VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
        label.pLabelName = name.c_str();
        gBeginLabel(mCmd, &label);
    }
    if (mTimer) mTimer->begin(mCmd, name);
}

void CommandList::endPass() {
    if (mTimer) mTimer->end(mCmd);
    if (gEndLabel) gEndLabel(mCmd);
}

void CommandList::barrier() {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                      VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT |
                      VK_ACCESS_HOST_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    VkPipelineStageFlags stages =
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(mCmd, stages,
                         stages | VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                         0, 1, &b, 0, nullptr, 0, nullptr);
    mRead.clear();
    mWritten.clear();
    ++mBarriers;
}

void CommandList::access(std::span<const Buffer* const> reads,
                         std::span<const Buffer* const> writes) {
    auto in = [](const std::vector<VkBuffer>& set, const Buffer* b) {
        return std::find(set.begin(), set.end(), b->handle()) != set.end();
    };
    bool dependent = false;
    for (const Buffer* b : reads) dependent = dependent || in(mWritten, b);  // read after write
    for (const Buffer* b : writes)
        dependent = dependent || in(mWritten, b) || in(mRead, b);  // after a write or read
    if (dependent) barrier();
    for (const Buffer* b : reads) {
        if (!in(mRead, b)) mRead.push_back(b->handle());
    }
    for (const Buffer* b : writes) {
        if (!in(mWritten, b)) mWritten.push_back(b->handle());
    }
}

void CommandList::copyBuffer(const Buffer& src, const Buffer& dst,
                             const std::vector<VkBufferCopy>& regions) {
    if (regions.empty()) return;
    const Buffer* read[] = {&src};
    const Buffer* written[] = {&dst};
    access(read, written);
    vkCmdCopyBuffer(mCmd, src.handle(), dst.handle(), static_cast<std::uint32_t>(regions.size()),
                    regions.data());
}

void CommandList::fillBuffer(const Buffer& dst, std::uint32_t value) {
    const Buffer* written[] = {&dst};
    access({}, written);
    vkCmdFillBuffer(mCmd, dst.handle(), 0, VK_WHOLE_SIZE, value);
}

}  // namespace engine::gpu
