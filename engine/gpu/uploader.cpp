#include "gpu/uploader.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "core/check.h"
#include "gpu/command_list.h"
#include "gpu/context.h"

namespace engine::gpu {

Uploader::Uploader(Context& ctx, std::uint64_t chunkBytes) : mCtx(ctx), mChunkBytes(chunkBytes) {}

void Uploader::write(const Buffer& dst, std::uint64_t offset, const void* data,
                     std::uint64_t bytes) {
    if (bytes == 0) return;
    CHECK_MSG(offset + bytes <= dst.size(), "upload past the end of %s", dst.name().c_str());
    if (!mData.empty() && mData.size() + bytes > mChunkBytes) sendChunk();
    std::uint64_t at = mData.size();
    mData.resize(at + bytes);
    std::memcpy(mData.data() + at, data, bytes);
    mPeakQueued = std::max<std::uint64_t>(mPeakQueued, mData.size());
    std::vector<VkBufferCopy>& copies = mCopies[&dst];
    // Merge with the previous region when both source and destination continue it.
    if (!copies.empty() && copies.back().srcOffset + copies.back().size == at &&
        copies.back().dstOffset + copies.back().size == offset) {
        copies.back().size += bytes;
    } else {
        copies.push_back({at, offset, bytes});
    }
}

UploadStats Uploader::record(CommandList& cmd) {
    UploadStats stats;
    if (mData.empty()) return stats;
    CHECK_MSG(mLastRecordSubmission != mCtx.completedSubmissions(),
              "Uploader::record twice in one submission would overwrite staging memory in use");
    mLastRecordSubmission = mCtx.completedSubmissions();
    if (!mStaging.valid() || mStaging.size() < mData.size()) {
        mStaging =
            Buffer(mCtx, BufferKind::Staging,
                   std::bit_ceil(std::max<std::uint64_t>(mData.size(), 1 << 16)), "upload.staging");
    }
    copyQueued(cmd, mStaging, stats);
    return stats;
}

void Uploader::copyQueued(CommandList& cmd, Buffer& staging, UploadStats& stats) {
    staging.write(mData.data(), mData.size());
    for (auto& [dst, copies] : mCopies) {
        cmd.copyBuffer(staging, *dst, copies);
        stats.regions += copies.size();
    }
    stats.bytes += mData.size();
    // The world's brick pages are read by address, which declares no binding: wait here.
    cmd.barrier();
    mData.clear();
    mCopies.clear();
}

void Uploader::sendChunk() {
    if (!mChunkStaging.valid() || mChunkStaging.size() < mData.size()) {
        mChunkStaging = Buffer(mCtx, BufferKind::Staging,
                               std::bit_ceil(std::max<std::uint64_t>(mData.size(), 1 << 16)),
                               "upload.chunkStaging");
    }
    CommandList cmd(mCtx);
    cmd.begin();
    UploadStats ignored;
    copyQueued(cmd, mChunkStaging, ignored);
    cmd.submitAndWait();
    ++mChunksSent;
}

}  // namespace engine::gpu
