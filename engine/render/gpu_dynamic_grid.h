// GpuDynamicGrid: the GPU copy of a scene's dynamic grid (world/dynamic_grid.h), one buffer laid
// out as shaders/shared/dynamic_grid.h says. The grid is small and rebuilt whenever an object
// moves, so a changed grid is uploaded whole (no dirty tracking); an unchanged one (same
// revision) costs nothing. Shaders find it through BrickGridInfo::dynamicGrid, which GpuWorld
// fills with address() — so the world bindings stay as they are.
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
    explicit GpuDynamicGrid(gpu::Context& ctx) : mCtx(ctx) {}

    // Queues the upload if `grid` changed since the last sync; returns the bytes queued.
    std::uint64_t sync(const world::DynamicGrid& grid, gpu::Uploader& uploader);
    // Device address of the buffer, 0 when there are no objects.
    std::uint64_t address() const { return mPresent ? mBuffer.deviceAddress() : 0u; }
    std::uint64_t bytes() const { return mBuffer.valid() ? mBuffer.size() : 0u; }
    void invalidate() { mSynced = false; }

private:
    gpu::Context& mCtx;
    gpu::Buffer mBuffer;
    bool mSynced = false;
    bool mPresent = false;
    std::uint64_t mRevision = 0;
};

}  // namespace engine::render
