// GpuWorld: the GPU mirror of a Scene's BrickGrid, palette and dynamic grid (world bindings 0-4 of
// every ray-tracing shader, see shaders/shared/bindings.h).
//
// The first sync uploads everything; later syncs upload only the bricks, top-grid cells, region
// table entries and pages the grid marked changed (the caller then clears the marks). The top
// grid is paged as on the CPU (world/paged_top_grid.h): the GPU holds the region table and room
// for the pages and for the brick masks' copy (doubling; outgrowing it builds the grid texels
// again, but not the bricks, and is not a new world). The brick pool lives in pages
// of BRICK_PAGE_BRICKS bricks, each its own buffer reached by device address, so no binding exceeds
// lavapipe's 128 MiB limit however large the world grows.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "render/gpu_dynamic_grid.h"
#include "world/scene.h"

namespace engine::gpu {
class Context;
class Uploader;
}  // namespace engine::gpu

namespace engine::render {

struct WorldUploadStats {
    bool full = false;         // everything was (re)uploaded
    std::uint32_t bricks = 0;  // bricks uploaded
    std::uint32_t cells = 0;   // top-grid cells uploaded
    std::uint64_t bytes = 0;
    std::uint64_t dynamicBytes =
        0;  // the dynamic grid, uploaded whole when it changed (0: unchanged)
};

struct GpuWorldMemory {
    std::uint64_t topGridBytes = 0;
    std::uint64_t brickPageBytes = 0;
    std::uint32_t brickPages = 0;
    std::uint64_t pageTableBytes = 0;
    std::uint64_t paletteBytes = 0;
    std::uint64_t dynamicGridBytes = 0;
};

class GpuWorld {
public:
    explicit GpuWorld(gpu::Context& ctx);

    // Queues the uploads that bring the GPU copy up to date with `scene`. Record the uploader
    // afterwards; the caller clears the grid's dirty marks once every consumer has seen them.
    WorldUploadStats sync(const world::Scene& scene, gpu::Uploader& uploader);
    // The next sync uploads everything (a new or resized world).
    bool needsFullUpload(const world::BrickGrid& grid) const {
        return grid.sizeInCells() != mSizeInCells;
    }
    // Forget the GPU state: the next sync uploads everything.
    void invalidate() {
        mSizeInCells = glm::ivec3(0);
        mCellPageCapacity = 0;
        mBrickPageRoom = 0;
        mDynamic.invalidate();
    }

    const gpu::Buffer& info() const { return mInfo; }
    const gpu::Buffer& cells() const { return mCells; }
    const gpu::Buffer& pageTable() const { return mPageTable; }
    const gpu::Buffer& palette() const { return mPalette; }
    const gpu::Buffer& dynamicGridTexels() const { return mDynamic.buffer(); }
    GpuWorldMemory memory() const;

private:
    void ensurePages(std::uint32_t brickCapacity, gpu::Uploader& uploader);
    void uploadBricks(const world::BrickGrid& grid, std::vector<std::uint32_t>& bricks,
                      gpu::Uploader& uploader);
    // The mask copy in the grid texels alone (the traversal's), for `bricks`.
    void uploadMaskCopy(const world::BrickGrid& grid, std::vector<std::uint32_t>& bricks,
                        gpu::Uploader& uploader);

    gpu::Context& mCtx;
    glm::ivec3 mSizeInCells{0};
    std::uint64_t mCellPageCapacity = 0;  // top-grid pages the grid texels hold room for
    std::uint64_t mBrickPageRoom = 0;     // brick pages the grid texels' mask copy holds room for
    std::uint64_t mMaskBase = 0;          // first texel of the mask copy
    gpu::Buffer mInfo, mCells, mPageTable, mPalette;
    std::vector<gpu::Buffer> mPages;
    std::vector<shared::GpuMaterial> mUploadedPalette;
    GpuDynamicGrid mDynamic;  // scene.dynamic, world binding 4
};

}  // namespace engine::render
