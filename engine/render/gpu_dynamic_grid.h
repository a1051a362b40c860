// GpuDynamicGrid: the GPU copy of a scene's dynamic grid (world/dynamic_grid.h), one buffer laid
// out as shaders/shared/dynamic_grid.h says, read by shaders through its R32_UINT texel view
// (world binding 4). The grid is small and rebuilt whenever an object moves, so a changed grid is
// uploaded whole (no dirty tracking); an unchanged one (same revision) costs nothing. Shaders
// read it only when BrickGridInfo::dynamicGrid.x says it is present(); the binding always holds a
// buffer, a small unused one when there are no objects.
#pragma once

#include <cstdint>

#include "gpu/buffer.h"
#include "world/dynamic_grid.h"

namespace engine::gpu {
class Context;
class Uploader;
}  // namespace engine::gpu

namespace engine::render {

class GpuDynamicGrid {
public:
    explicit GpuDynamicGrid(gpu::Context& ctx);

    // Queues the upload if `grid` changed since the last sync; returns the bytes queued.
    std::uint64_t sync(const world::DynamicGrid& grid, gpu::Uploader& uploader);
    // Whether the last sync had objects (else shaders must not read the buffer).
    bool present() const { return mPresent; }
    // The buffer for world binding 4 (a small unused one until there are objects).
    const gpu::Buffer& buffer() const { return mBuffer; }
    std::uint64_t bytes() const { return mBuffer.valid() ? mBuffer.size() : 0u; }
    void invalidate() { mSynced = false; }

private:
    void allocate(std::uint64_t bytes);

    gpu::Context& mCtx;
    gpu::Buffer mBuffer;
    bool mSynced = false;
    bool mPresent = false;
    std::uint64_t mRevision = 0;
};

}  // namespace engine::render
