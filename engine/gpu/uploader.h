// gpu::Uploader: queues host data for device buffers, then records it as one staging copy per
// destination buffer. Counts what it moved so callers (and tests) can see that only dirty
// data travels. A burst larger than kChunkBytes (a whole new world) is sent ahead in chunks of
// its own submissions, so the host never holds a second copy of a multi-GiB brick pool.
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
    explicit Uploader(Context& ctx, std::uint64_t chunkBytes = kChunkBytes);

    static constexpr std::uint64_t kChunkBytes = 128ull << 20;

    void write(const Buffer& dst, std::uint64_t offset, const void* data, std::uint64_t bytes);
    bool pending() const { return !mData.empty(); }
    // Records the copies and a barrier. The staging memory is reused by the next record(), which
    // must come after this command list has completed.
    UploadStats record(CommandList& cmd);

    std::uint64_t chunksSent() const { return mChunksSent; }
    std::uint64_t peakQueuedBytes() const { return mPeakQueued; }  // host copy held at once

private:
    // Copies what is queued through mChunkStaging in a submission of its own and waits for it.
    void sendChunk();
    void copyQueued(CommandList& cmd, Buffer& staging, UploadStats& stats);

    Context& mCtx;
    Buffer mStaging;
    Buffer mChunkStaging;  // separate: mStaging may be recorded into a list not yet submitted
    std::uint64_t mChunkBytes;
    std::uint64_t mChunksSent = 0;
    std::uint64_t mPeakQueued = 0;
    std::vector<std::uint8_t> mData;
    std::map<const Buffer*, std::vector<VkBufferCopy>> mCopies;
    std::uint64_t mLastRecordSubmission = UINT64_MAX;
};

}  // namespace engine::gpu
