// gpu::Uploader: queues host data for device buffers, then records it as one staging copy per
// destination buffer. Counts what it moved so callers (and tests) can see that only dirty
// data travels.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "gpu/buffer.h"

namespace engine::gpu {

class CommandList;
class Context;

struct UploadStats {
    std::uint64_t bytes = 0;
    std::uint64_t regions = 0;
};

class Uploader {
public:
    explicit Uploader(Context& ctx);

    void write(const Buffer& dst, std::uint64_t offset, const void* data, std::uint64_t bytes);
    bool pending() const { return !mData.empty(); }
    // Records the copies and a barrier. The staging memory is reused by the next record(), which
    // must come after this command list has completed.
    UploadStats record(CommandList& cmd);

private:
    Context& mCtx;
    Buffer mStaging;
    std::vector<std::uint8_t> mData;
    std::map<const Buffer*, std::vector<VkBufferCopy>> mCopies;
    std::uint64_t mLastRecordSubmission = UINT64_MAX;
};

}  // namespace engine::gpu
