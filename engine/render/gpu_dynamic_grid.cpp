#include "render/gpu_dynamic_grid.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include "core/check.h"
#include "gpu/context.h"
#include "gpu/texel_buffer_limit.h"
#include "gpu/uploader.h"
#include "shared/brick_grid.h"
#include "shared/dynamic_grid.h"

namespace engine::render {

GpuDynamicGrid::GpuDynamicGrid(gpu::Context& ctx) : mCtx(ctx) { allocate(0); }

std::uint64_t GpuDynamicGrid::sync(const world::DynamicGrid& grid, gpu::Uploader& uploader) {
    if (mSynced && grid.revision == mRevision) return 0;
    if (!grid.present()) {
        mSynced = true;
        mRevision = grid.revision;
        mPresent = false;
        return 0;
    }

    const world::BrickGrid& g = grid.grid;
    // The objects' grid is small and uploaded whole: its cells as a dense array (the shaders
    // read the dynamic grid without a region table).
    std::span<const std::uint32_t> supers = g.superCells();
    // Live bricks only, renumbered densely (the pool may hold free slots).
    std::vector<std::uint32_t> cellWords = g.denseCells();
    std::vector<std::uint32_t> bricks;
    for (std::uint32_t& c : cellWords) {
        if (!world::BrickGrid::cellIsBrick(c)) continue;
        bricks.push_back(world::BrickGrid::cellBrick(c));
        c = std::uint32_t(bricks.size());  // brickIndex + 1
    }
    auto align4 = [](std::size_t w) { return (w + 3u) & ~std::size_t(3u); };
    shared::DynamicGridHeader h{};
    h.origin = glm::ivec4(grid.origin, int(grid.instances.size()));
    h.sizeInCells = glm::ivec4(g.sizeInCells(), 0);
    h.sizeInVoxels = glm::ivec4(g.sizeInVoxels(), 0);
    h.sizeInSuperCells = glm::ivec4(g.sizeInSuperCells(), 0);
    CHECK(grid.occupancy.size() <= shared::DYNAMIC_OCCUPANCY_BOXES);
    h.objects.y = std::uint32_t(grid.occupancy.size());
    for (std::size_t i = 0; i < grid.occupancy.size(); ++i) {
        h.occupiedMin[i] = glm::ivec4(grid.occupancy[i].min, 0);
        h.occupiedMax[i] = glm::ivec4(grid.occupancy[i].max, 0);
    }
    std::size_t words =
        shared::DYNAMIC_HEADER_TEXELS;   // offsets count texels from the buffer's start
    h.offsets.x = std::uint32_t(words);  // right after the header: shaders take that for granted
    words = align4(words + supers.size());
    h.offsets.y = std::uint32_t(words);
    words = align4(words + cellWords.size());
    h.offsets.z = std::uint32_t(words);
    words += bricks.size() * shared::BRICK_MASK_WORDS;
    h.offsets.w = std::uint32_t(words);
    words += bricks.size() * shared::BRICK_MATERIAL_WORDS;
    words = align4(words);
    h.objects.x = std::uint32_t(words);
    words += grid.instances.size() * (sizeof(shared::GpuDynamicObject) / 4u);

    static_assert(sizeof(h) == shared::DYNAMIC_HEADER_TEXELS * 4u);
    static_assert(sizeof(shared::GpuDynamicObject) == shared::DYNAMIC_OBJECT_TEXELS * 4u);
    std::vector<std::uint32_t> data(words, 0u);
    std::uint32_t* w = data.data();
    std::memcpy(data.data(), &h, sizeof(h));
    std::copy(supers.begin(), supers.end(), w + h.offsets.x);
    std::copy(cellWords.begin(), cellWords.end(), w + h.offsets.y);
    for (std::size_t i = 0; i < bricks.size(); ++i) {
        std::memcpy(w + h.offsets.z + i * shared::BRICK_MASK_WORDS,
                    g.brickMask(bricks[i]).words.data(), shared::BRICK_MASK_WORDS * 4u);
        std::memcpy(w + h.offsets.w + i * shared::BRICK_MATERIAL_WORDS,
                    g.brickVoxels(bricks[i]).data(), shared::BRICK_MATERIAL_WORDS * 4u);
    }
    for (std::size_t i = 0; i < grid.instances.size(); ++i) {
        const world::DynamicInstance& inst = grid.instances[i];
        shared::GpuDynamicObject o{};
        o.boundsMin = glm::ivec4(inst.bounds.min, 0);
        o.boundsMax = glm::ivec4(inst.bounds.max, 0);
        o.prevFromCurrent = glm::mat4(inst.prevFromCurrent());
        std::memcpy(w + h.objects.x + i * (sizeof(o) / 4u), &o, sizeof(o));
    }

    // One texel view holds it all: refused, with the count, before the GPU copy changes.
    gpu::checkTexelCount(mCtx, data.size(), "the dynamic objects' grid");
    const std::uint64_t bytes = data.size() * 4u;
    if (mBuffer.size() < bytes) {
        // Grows by powers of two so an object moving about does not reallocate every frame, up
        // to the view's limit.
        allocate(std::min(std::bit_ceil(bytes), mCtx.info().maxTexelBufferElements * 4u));
    }
    uploader.write(mBuffer, 0, data.data(), bytes);
    mSynced = true;
    mRevision = grid.revision;
    mPresent = true;
    return bytes;
}

void GpuDynamicGrid::allocate(std::uint64_t bytes) {
    gpu::Buffer bigger(mCtx, gpu::BufferKind::Storage, std::max<std::uint64_t>(bytes, 4096),
                       "world.dynamicGrid");
    bigger.setTexelFormat(VK_FORMAT_R32_UINT);
    mBuffer = std::move(bigger);
}

}  // namespace engine::render
