#include "render/gpu_world.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>

#include "gpu/context.h"
#include "gpu/texel_buffer_limit.h"
#include "gpu/uploader.h"
#include "shared/brick_grid.h"

namespace engine::render {

namespace {
constexpr std::uint64_t kPageBytes = std::uint64_t(shared::BRICK_PAGE_WORDS) * 4u;
constexpr std::uint64_t kMaskBytes = shared::BRICK_MASK_WORDS * 4u;
constexpr std::uint64_t kMaterialBytes = shared::BRICK_MATERIAL_WORDS * 4u;
static_assert(sizeof(world::BrickVoxels) == kMaterialBytes);
static_assert(sizeof(world::BrickMask) == kMaskBytes);

std::uint32_t pagesFor(std::uint32_t brickCapacity) {
    return std::max<std::uint32_t>(
        1, (brickCapacity + shared::BRICK_PAGE_BRICKS - 1) >> shared::BRICK_PAGE_SHIFT);
}

bool samePalette(const std::vector<shared::GpuMaterial>& a,
                 const std::vector<shared::GpuMaterial>& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(shared::GpuMaterial)) == 0;
}
}  // namespace

GpuWorld::GpuWorld(gpu::Context& ctx) : mCtx(ctx), mDynamic(ctx) {}

WorldUploadStats GpuWorld::sync(const world::Scene& scene, gpu::Uploader& uploader) {
    const world::BrickGrid& grid = scene.grid;
    WorldUploadStats stats;

    // The grid texels (below) must fit one texel view: refused before anything is allocated or
    // changed, so a world over the device's limit leaves the GPU copy as it was.
    const std::uint64_t pages =
        std::max<std::uint64_t>(mPages.size(), pagesFor(grid.brickCapacity()));
    gpu::checkTexelCount(mCtx,
                         grid.cells().size() + grid.superCells().size() +
                             pages * shared::BRICK_PAGE_BRICKS * shared::BRICK_MASK_WORDS,
                         "world '" + scene.name + "'");

    std::vector<shared::GpuMaterial> palette = scene.palette.toGpu();
    if (!samePalette(palette, mUploadedPalette)) {
        std::uint64_t bytes = palette.size() * sizeof(shared::GpuMaterial);
        if (!mPalette.valid() || mPalette.size() < bytes) {
            mPalette = gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                                   std::max<std::uint64_t>(bytes, 64 * 48), "world.palette");
            mPalette.setTexelFormat(
                VK_FORMAT_R32G32B32A32_UINT);  // GpuMaterial: 3 texels (materialAlbedo)
        }
        uploader.write(mPalette, 0, palette.data(), bytes);
        stats.bytes += bytes;
        mUploadedPalette = std::move(palette);
    }

    ensurePages(grid.brickCapacity(), uploader);
    // The grid texels: the cells, the super cells, then every brick slot's mask words (a copy of
    // the pages' masks that the traversal reads as texels, without the page table). More pages
    // outgrow the mask copy: then everything is uploaded again, as for a new world.
    const std::uint64_t gridTexelBytes = grid.cells().size_bytes() + grid.superCells().size_bytes();
    const std::uint64_t texelBytes =
        gridTexelBytes + mPages.size() * shared::BRICK_PAGE_BRICKS * kMaskBytes;
    if (needsFullUpload(grid) || mCells.size() != texelBytes) {
        // A new or resized world: upload the top grid and every live brick.
        stats.full = true;
        mSizeInCells = grid.sizeInCells();
        std::span<const std::uint32_t> cells = grid.cells();
        std::span<const std::uint32_t> supers = grid.superCells();
        mCells = gpu::Buffer(mCtx, gpu::BufferKind::Storage, texelBytes, "world.cells");
        mCells.setTexelFormat(VK_FORMAT_R32_UINT);
        mInfo = gpu::Buffer(mCtx, gpu::BufferKind::Storage, sizeof(shared::BrickGridInfo),
                            "world.info");
        uploader.write(mCells, cells.size_bytes(), supers.data(), supers.size_bytes());
        stats.bytes += supers.size_bytes();
        uploader.write(mCells, 0, cells.data(), cells.size_bytes());
        stats.cells = static_cast<std::uint32_t>(cells.size());
        stats.bytes += cells.size_bytes();
        std::vector<std::uint32_t> live;
        for (std::uint32_t c : cells) {
            if (world::BrickGrid::cellIsBrick(c)) live.push_back(world::BrickGrid::cellBrick(c));
        }
        uploadBricks(grid, live, uploader);
        stats.bricks = static_cast<std::uint32_t>(live.size());
    } else {
        std::vector<std::uint32_t> dirty(grid.dirtyCells().begin(), grid.dirtyCells().end());
        std::sort(dirty.begin(), dirty.end());
        std::span<const std::uint32_t> cells = grid.cells();
        // Runs of consecutive cells become one region each.
        for (std::size_t i = 0; i < dirty.size();) {
            std::size_t j = i + 1;
            while (j < dirty.size() && dirty[j] == dirty[j - 1] + 1) ++j;
            uploader.write(mCells, std::uint64_t(dirty[i]) * 4u, &cells[dirty[i]], (j - i) * 4u);
            stats.bytes += (j - i) * 4u;
            i = j;
        }
        stats.cells = static_cast<std::uint32_t>(dirty.size());
        std::span<const std::uint32_t> supers = grid.superCells();
        for (std::uint32_t s : grid.dirtySuperCells()) {
            uploader.write(mCells, cells.size_bytes() + std::uint64_t(s) * 4u, &supers[s], 4u);
            stats.bytes += 4u;
        }
        std::vector<std::uint32_t> bricks(grid.dirtyBricks().begin(), grid.dirtyBricks().end());
        uploadBricks(grid, bricks, uploader);
        stats.bricks = static_cast<std::uint32_t>(bricks.size());
    }
    stats.bytes += std::uint64_t(stats.bricks) * (2 * kMaskBytes + kMaterialBytes);

    stats.dynamicBytes = mDynamic.sync(scene.dynamic, uploader);
    stats.bytes += stats.dynamicBytes;

    shared::BrickGridInfo info{};
    info.sizeInCells = glm::ivec4(grid.sizeInCells(), 0);
    info.sizeInVoxels = glm::ivec4(grid.sizeInVoxels(), 0);
    info.sizeInSuperCells = glm::ivec4(grid.sizeInSuperCells(), 0);
    info.counts = glm::uvec4(grid.liveBricks(), static_cast<std::uint32_t>(mPages.size()),
                             static_cast<std::uint32_t>(scene.palette.size()), 0u);
    info.dynamicGrid = glm::uvec4(mDynamic.present() ? 1u : 0u, 0u, 0u, 0u);
    uploader.write(mInfo, 0, &info, sizeof(info));
    return stats;
}

void GpuWorld::ensurePages(std::uint32_t brickCapacity, gpu::Uploader& uploader) {
    std::uint32_t needed = pagesFor(brickCapacity);
    if (needed <= mPages.size() && mPageTable.valid()) return;
    std::uint64_t tableBytes = std::uint64_t(needed) * sizeof(std::uint64_t);
    if (!mPageTable.valid() || mPageTable.size() < tableBytes) {
        std::uint64_t capacity = std::max<std::uint64_t>(64, std::bit_ceil(std::uint64_t(needed)));
        mPageTable = gpu::Buffer(mCtx, gpu::BufferKind::Storage, capacity * sizeof(std::uint64_t),
                                 "world.pageTable");
        mPageTable.setTexelFormat(VK_FORMAT_R32G32_UINT);
    }
    while (mPages.size() < needed) {
        mPages.emplace_back(mCtx, gpu::BufferKind::Storage, kPageBytes,
                            "world.brickPage" + std::to_string(mPages.size()));
    }
    std::vector<std::uint64_t> addresses;
    for (const gpu::Buffer& page : mPages) addresses.push_back(page.deviceAddress());
    uploader.write(mPageTable, 0, addresses.data(), addresses.size() * sizeof(std::uint64_t));
}

void GpuWorld::uploadBricks(const world::BrickGrid& grid, std::vector<std::uint32_t>& bricks,
                            gpu::Uploader& uploader) {
    // Sorted, masks first and materials second: runs of neighbouring bricks then merge into one
    // copy region each (the uploader joins adjacent regions).
    std::sort(bricks.begin(), bricks.end());
    for (std::uint32_t brick : bricks) {
        std::uint64_t local = brick & (shared::BRICK_PAGE_BRICKS - 1u);
        uploader.write(mPages[brick >> shared::BRICK_PAGE_SHIFT], local * kMaskBytes,
                       grid.brickMask(brick).words.data(), kMaskBytes);
    }
    const std::uint64_t maskTexels = grid.cells().size_bytes() + grid.superCells().size_bytes();
    for (std::uint32_t brick : bricks) {
        uploader.write(mCells, maskTexels + std::uint64_t(brick) * kMaskBytes,
                       grid.brickMask(brick).words.data(), kMaskBytes);
    }
    for (std::uint32_t brick : bricks) {
        std::uint64_t local = brick & (shared::BRICK_PAGE_BRICKS - 1u);
        uploader.write(
            mPages[brick >> shared::BRICK_PAGE_SHIFT],
            std::uint64_t(shared::BRICK_PAGE_MATERIAL_OFFSET) * 4u + local * kMaterialBytes,
            grid.brickVoxels(brick).data(), kMaterialBytes);
    }
}

GpuWorldMemory GpuWorld::memory() const {
    GpuWorldMemory m;
    m.topGridBytes = mCells.valid() ? mCells.size() : 0;
    m.brickPages = static_cast<std::uint32_t>(mPages.size());
    m.brickPageBytes = mPages.size() * kPageBytes;
    m.pageTableBytes = mPageTable.valid() ? mPageTable.size() : 0;
    m.paletteBytes = mPalette.valid() ? mPalette.size() : 0;
    m.dynamicGridBytes = mDynamic.bytes();
    return m;
}

}  // namespace engine::render
