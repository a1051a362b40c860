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

// Cell pages and brick pages the grid texels keep room for: doubling, so a world that streams in
// rebuilds its grid texels a few times (log2 of its size), not at every new page.
std::uint64_t cellPageCapacity(std::uint32_t pages) {
    return std::max<std::uint64_t>(8, std::bit_ceil(std::uint64_t(pages)));
}
std::uint64_t brickPageRoom(std::uint64_t pages) {
    return std::max<std::uint64_t>(1, std::bit_ceil(pages));
}

// Where each part of the grid texels starts (shared/brick_grid.h).
struct TexelLayout {
    std::uint64_t table = 0, pages = 0, masks = 0, total = 0;
};
TexelLayout texelLayout(const world::BrickGrid& grid, std::uint64_t pageCapacity,
                        std::uint64_t brickPages) {
    TexelLayout l;
    l.table = grid.superCells().size();
    l.pages = l.table + grid.topGrid().table().size();
    l.masks = l.pages + pageCapacity * shared::PAGE_CELLS;
    l.total = l.masks + brickPages * shared::BRICK_PAGE_BRICKS * shared::BRICK_MASK_WORDS;
    return l;
}

// A super cell as the GPU holds it: an occupied one names its region's top-grid page.
std::uint32_t gpuSuperCell(const world::BrickGrid& grid, std::size_t index) {
    const std::uint32_t skip = grid.superCells()[index];
    if (skip != 0) return skip;
    const glm::ivec3 n = grid.sizeInSuperCells();
    const std::size_t yz = index / std::size_t(n.x);
    const glm::ivec3 s(int(index % std::size_t(n.x)), int(yz % std::size_t(n.y)),
                       int(yz / std::size_t(n.y)));
    const world::PagedTopGrid& top = grid.topGrid();
    return top.table()[top.regionIndex(s << 2)] << shared::SUPER_PAGE_SHIFT;
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
    const world::PagedTopGrid& top = grid.topGrid();
    // Room for cell pages and brick masks only grows within one world (a new world starts
    // afresh).
    const bool newWorld = needsFullUpload(grid);
    const std::uint64_t pageCapacity =
        newWorld ? cellPageCapacity(top.pageCount())
                 : std::max<std::uint64_t>(mCellPageCapacity, cellPageCapacity(top.pageCount()));
    const std::uint64_t maskRoom =
        newWorld ? brickPageRoom(pages) : std::max(mBrickPageRoom, brickPageRoom(pages));
    const TexelLayout layout = texelLayout(grid, pageCapacity, maskRoom);
    gpu::checkTexelCount(mCtx, layout.total, "world '" + scene.name + "'");

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
    // The grid texels: the super cells, the region table, the cell pages, then every brick
    // slot's mask words (a copy of the pages' masks that the traversal reads as texels, without
    // the page table). More brick pages than the mask copy has room for, or more cell pages: the
    // grid texels are built again, from the host.
    const TexelLayout uploaded = texelLayout(grid, pageCapacity, maskRoom);
    mMaskBase = uploaded.masks;
    if (newWorld || mCells.size() != uploaded.total * 4u) {
        // A new or resized world uploads the top grid and every live brick. Room outgrown within
        // one world (streaming, a large edit) rebuilds only the grid texels: the brick pages,
        // buffers of their own, already hold every brick but this frame's dirty ones, and the
        // world is not new to the lighting (no cache cleared, no history lost). Uploading every
        // brick again as a new world was what made a streamed flight's slowest frames (issue
        // 39): once per 4096 bricks streamed in.
        stats.full = newWorld;
        mSizeInCells = grid.sizeInCells();
        mCellPageCapacity = pageCapacity;
        mBrickPageRoom = maskRoom;
        mCells = gpu::Buffer(mCtx, gpu::BufferKind::Storage, uploaded.total * 4u, "world.cells");
        mCells.setTexelFormat(VK_FORMAT_R32_UINT);
        mInfo = gpu::Buffer(mCtx, gpu::BufferKind::Storage, sizeof(shared::BrickGridInfo),
                            "world.info");
        std::vector<std::uint32_t> supers(grid.superCells().size());
        for (std::size_t s = 0; s < supers.size(); ++s) supers[s] = gpuSuperCell(grid, s);
        uploader.write(mCells, 0, supers.data(), supers.size() * 4u);
        uploader.write(mCells, uploaded.table * 4u, top.table().data(), top.table().size_bytes());
        for (std::uint32_t page = 0; page < top.pageCount(); ++page) {
            uploader.write(mCells, (uploaded.pages + std::uint64_t(page) * shared::PAGE_CELLS) * 4u,
                           top.pageCells(page), shared::PAGE_CELLS * 4u);
        }
        stats.cells = top.pageCount() * shared::PAGE_CELLS;
        stats.bytes += (supers.size() + top.table().size() + stats.cells) * 4u;
        std::vector<std::uint32_t> live;
        top.forEachLiveCell([&](std::uint32_t c) {
            if (world::BrickGrid::cellIsBrick(c)) live.push_back(world::BrickGrid::cellBrick(c));
        });
        if (newWorld) {
            uploadBricks(grid, live, uploader);
            stats.bricks = static_cast<std::uint32_t>(live.size());
        } else {
            uploadMaskCopy(grid, live, uploader);
            stats.bytes += live.size() * kMaskBytes;
            std::vector<std::uint32_t> bricks(grid.dirtyBricks().begin(), grid.dirtyBricks().end());
            uploadBricks(grid, bricks, uploader);
            stats.bricks = static_cast<std::uint32_t>(bricks.size());
        }
    } else {
        // Regions whose page changed: the table entry, the whole page (a page number a region
        // reuses holds another region's old cells on the GPU) and the region's super cells
        // (occupied ones name the page).
        std::vector<std::uint8_t> wholePage(top.table().size(), 0);
        std::vector<std::uint32_t> supers(grid.dirtySuperCells().begin(),
                                          grid.dirtySuperCells().end());
        const glm::ivec3 superSize = grid.sizeInSuperCells();
        const glm::ivec3 regions = top.sizeInRegions();
        for (std::uint32_t r : top.changedRegions()) {
            const std::uint32_t page = top.table()[r];
            uploader.write(mCells, (uploaded.table + r) * 4u, &top.table()[r], 4u);
            stats.bytes += 4u;
            if (page != world::PagedTopGrid::kEmptyPage) {
                uploader.write(mCells,
                               (uploaded.pages + std::uint64_t(page) * shared::PAGE_CELLS) * 4u,
                               top.pageCells(page), shared::PAGE_CELLS * 4u);
                stats.cells += shared::PAGE_CELLS;
                stats.bytes += shared::PAGE_CELLS * 4u;
                wholePage[r] = 1;
            }
            const std::size_t yz = r / std::size_t(regions.x);
            const glm::ivec3 lo =
                glm::ivec3(int(r % std::size_t(regions.x)), int(yz % std::size_t(regions.y)),
                           int(yz / std::size_t(regions.y))) *
                4;
            const glm::ivec3 hi = glm::min(lo + 4, superSize);
            for (int z = lo.z; z < hi.z; ++z)
                for (int y = lo.y; y < hi.y; ++y)
                    for (int x = lo.x; x < hi.x; ++x)
                        supers.push_back(std::uint32_t(grid.superCellIndex({x, y, z})));
        }
        // The other dirty cells, by texel; runs of consecutive texels become one copy each.
        std::vector<std::uint64_t> texels;
        for (std::uint32_t index : grid.dirtyCells()) {
            const glm::ivec3 c = grid.cellOfIndex(index);
            const std::size_t r = top.regionIndex(c);
            if (wholePage[r] || top.table()[r] == world::PagedTopGrid::kEmptyPage) continue;
            texels.push_back(uploaded.pages + std::uint64_t(top.table()[r]) * shared::PAGE_CELLS +
                             std::uint64_t(world::PagedTopGrid::pageLocal(c)));
        }
        std::sort(texels.begin(), texels.end());
        auto cellAt = [&](std::uint64_t texel) -> const std::uint32_t* {
            const std::uint64_t local = texel - uploaded.pages;
            return top.pageCells(std::uint32_t(local / shared::PAGE_CELLS)) +
                   local % shared::PAGE_CELLS;
        };
        for (std::size_t i = 0; i < texels.size();) {
            std::size_t j = i + 1;
            // A run stays within one page (its cells are contiguous on the CPU too).
            while (j < texels.size() && texels[j] == texels[j - 1] + 1 &&
                   (texels[j] - uploaded.pages) % shared::PAGE_CELLS != 0)
                ++j;
            uploader.write(mCells, texels[i] * 4u, cellAt(texels[i]), (j - i) * 4u);
            stats.bytes += (j - i) * 4u;
            i = j;
        }
        stats.cells += static_cast<std::uint32_t>(texels.size());
        std::sort(supers.begin(), supers.end());
        supers.erase(std::unique(supers.begin(), supers.end()), supers.end());
        for (std::uint32_t s : supers) {
            const std::uint32_t value = gpuSuperCell(grid, s);
            uploader.write(mCells, std::uint64_t(s) * 4u, &value, 4u);
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
                             static_cast<std::uint32_t>(scene.palette.size()),
                             static_cast<std::uint32_t>(mMaskBase));
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

void GpuWorld::uploadMaskCopy(const world::BrickGrid& grid, std::vector<std::uint32_t>& bricks,
                              gpu::Uploader& uploader) {
    std::sort(bricks.begin(), bricks.end());
    for (std::uint32_t brick : bricks) {
        uploader.write(mCells, mMaskBase * 4u + std::uint64_t(brick) * kMaskBytes,
                       grid.brickMask(brick).words.data(), kMaskBytes);
    }
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
    uploadMaskCopy(grid, bricks, uploader);
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
