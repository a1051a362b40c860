// gpu::CommandList: one primary command buffer plus what must live until it completes
// (descriptor sets). Passes record into it between beginPass/endPass, which add a debug label
// and a GPU timestamp with the pass's name.
//
// Barriers follow from what each command declares it reads and writes (access()): a command
// waits behind a barrier only when it reads or writes a buffer written since the last barrier,
// or writes one read since then; commands that share nothing run without one between them
// (kajiya's render graph, Falcor's reflect()). Dispatches, copies and fills declare their
// buffers themselves. What is read by device address (the world's brick pages, the light tiles,
// ReGIR's grid) is not declared by its readers: its writer ends with barrier().
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>
#include <vulkan/vulkan.h>

#include "gpu/context.h"

namespace engine::gpu {

class Buffer;
class TimestampTimer;

class CommandList {
public:
    explicit CommandList(Context& ctx, TimestampTimer* timer = nullptr);
    ~CommandList();
    CommandList(const CommandList&) = delete;
    CommandList& operator=(const CommandList&) = delete;

    VkCommandBuffer handle() const { return mCmd; }
    Context& context() const { return mCtx; }

    void begin();
    // Ends recording, submits, waits, and releases per-submission resources. `sync` ties the
    // submission to a swapchain image (gpu/swapchain.h).
    void submitAndWait(const SubmitSync& sync = {});
    // Ends recording and submits without waiting, so the host can work while the GPU runs the
    // list. Call wait() before reading what it wrote or beginning it again.
    void submit(const SubmitSync& sync = {});
    void wait();

    void beginPass(const std::string& name);
    void endPass();

    // Make writes of the previous commands (compute or transfer) visible to the next ones, the
    // arguments of an indirect dispatch and host reads after the submission included.
    void barrier();
    // The next command reads `reads` and writes (or reads and writes) `writes`: records a barrier
    // first when it depends on an earlier command since the last one.
    void access(std::span<const Buffer* const> reads, std::span<const Buffer* const> writes);
    // Barriers recorded so far (explicit and derived), for tests.
    std::uint32_t barrierCount() const { return mBarriers; }
    void copyBuffer(const Buffer& src, const Buffer& dst, const std::vector<VkBufferCopy>& regions);
    void fillBuffer(const Buffer& dst, std::uint32_t value);

    // Values of the specialization constants (by constant_id) of every pipeline this list
    // dispatches from now on; empty (the start) leaves each constant at its default. The values
    // are copied.
    void setSpecialization(std::span<const std::uint32_t> values) {
        mSpecialization.assign(values.begin(), values.end());
    }
    std::span<const std::uint32_t> specialization() const { return mSpecialization; }

    // Descriptor sets allocated for this recording; freed after completion.
    void retainDescriptorSet(VkDescriptorPool pool, VkDescriptorSet set) {
        mDescriptorSets.emplace_back(pool, set);
    }

private:
    void finishRecording();
    void releaseSubmissionResources();

    Context& mCtx;
    TimestampTimer* mTimer;
    VkCommandBuffer mCmd = VK_NULL_HANDLE;
    bool mRecording = false;
    VkFence mFence = VK_NULL_HANDLE;  // made by the first submit()
    bool mPending = false;            // submitted, not yet waited for
    std::vector<std::pair<VkDescriptorPool, VkDescriptorSet>> mDescriptorSets;
    std::vector<std::uint32_t> mSpecialization;
    // Buffers read and written since the last barrier.
    std::vector<VkBuffer> mRead, mWritten;
    std::uint32_t mBarriers = 0;
};

}  // namespace engine::gpu
