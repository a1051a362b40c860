#include "render/vct/vct_block_list.h"

#include <algorithm>

namespace engine::render {

namespace {

constexpr int kBlocksPerAxis = int(shared::VCT_BLOCKS_PER_AXIS);
constexpr int kBlock = int(shared::VCT_BLOCK);

std::uint32_t blockIndex(std::uint32_t level, glm::ivec3 b) {
    return std::uint32_t(b.x + kBlocksPerAxis * (b.y + kBlocksPerAxis * b.z)) +
           level * shared::VCT_BLOCKS_PER_LEVEL;
}

// Calls f(b) for every block coordinate of a level.
template <class F>
void forEachBlock(F&& f) {
    for (int z = 0; z < kBlocksPerAxis; ++z)
        for (int y = 0; y < kBlocksPerAxis; ++y)
            for (int x = 0; x < kBlocksPerAxis; ++x) f(glm::ivec3(x, y, z));
}

// Block b's voxels in a level placed at p: [min, min + 4 texels).
glm::ivec3 blockMinVoxel(glm::ivec4 p, glm::ivec3 b) { return glm::ivec3(p) + b * (kBlock * p.w); }

}  // namespace

VctBlockList::VctBlockList()
    : mListed(std::size_t(shared::VCT_MAX_LEVELS) * shared::VCT_BLOCKS_PER_LEVEL, 0) {}

void VctBlockList::clear() { std::fill(mListed.begin(), mListed.end(), 0); }

void VctBlockList::addAll(std::uint32_t levels) {
    std::fill_n(mListed.begin(), std::size_t(levels) * shared::VCT_BLOCKS_PER_LEVEL, 1);
}

void VctBlockList::addNew(std::uint32_t level, glm::ivec4 now, glm::ivec4 before) {
    // World texel coordinates (origins are whole texels, so the division is exact).
    const glm::ivec3 first = glm::ivec3(now) / now.w;
    const bool sameSize = before.w == now.w;
    const glm::ivec3 beforeFirst = sameSize ? glm::ivec3(before) / before.w : glm::ivec3(0);
    const glm::ivec3 beforeEnd = beforeFirst + int(shared::VCT_RES);
    forEachBlock([&](glm::ivec3 b) {
        const glm::ivec3 lo = first + b * kBlock, hi = lo + kBlock;
        const bool inside = sameSize && glm::all(glm::greaterThanEqual(lo, beforeFirst)) &&
                            glm::all(glm::lessThanEqual(hi, beforeEnd));
        if (!inside) mListed[blockIndex(level, b)] = 1;
    });
}

void VctBlockList::addBox(std::uint32_t level, glm::ivec4 now, glm::ivec3 boxMin,
                          glm::ivec3 boxMax) {
    if (glm::any(glm::lessThanEqual(boxMax, boxMin))) return;
    forEachBlock([&](glm::ivec3 b) {
        const glm::ivec3 lo = blockMinVoxel(now, b), hi = lo + kBlock * now.w;
        if (glm::all(glm::lessThan(lo, boxMax)) && glm::all(glm::greaterThan(hi, boxMin)))
            mListed[blockIndex(level, b)] = 1;
    });
}

void VctBlockList::addContent(std::uint32_t level, glm::ivec4 now, const world::BrickGrid& grid,
                              std::uint64_t gridVersion) {
    ContentCache& cache = mContent[level];
    if (!cache.valid || cache.placement != now || cache.gridVersion != gridVersion) {
        cache.holds.assign(shared::VCT_BLOCKS_PER_LEVEL, 0);
        forEachBlock([&](glm::ivec3 b) {
            const glm::ivec3 lo = blockMinVoxel(now, b);
            cache.holds[blockIndex(0, b)] = holdsCell(grid, lo, lo + kBlock * now.w) ? 1 : 0;
        });
        cache.valid = true;
        cache.placement = now;
        cache.gridVersion = gridVersion;
    }
    for (std::uint32_t i = 0; i < shared::VCT_BLOCKS_PER_LEVEL; ++i)
        if (cache.holds[i]) mListed[level * shared::VCT_BLOCKS_PER_LEVEL + i] = 1;
}

std::span<const std::uint32_t> VctBlockList::blocks() {
    mBlocks.clear();
    for (std::uint32_t i = 0; i < mListed.size(); ++i)
        if (mListed[i]) mBlocks.push_back(i);
    return mBlocks;
}

bool VctBlockList::holdsCell(const world::BrickGrid& grid, glm::ivec3 lo, glm::ivec3 hi) {
    lo = glm::max(lo, glm::ivec3(0));
    hi = glm::min(hi, grid.sizeInVoxels());
    if (glm::any(glm::lessThanEqual(hi, lo))) return false;
    const glm::ivec3 c0 = lo >> 3, c1 = (hi - 1) >> 3;  // cells, inclusive
    const auto counts = grid.superCellCounts();
    for (int sz = c0.z >> 2; sz <= c1.z >> 2; ++sz)
        for (int sy = c0.y >> 2; sy <= c1.y >> 2; ++sy)
            for (int sx = c0.x >> 2; sx <= c1.x >> 2; ++sx) {
                const glm::ivec3 s(sx, sy, sz);
                if (counts[grid.superCellIndex(s)] == 0) continue;
                const glm::ivec3 a = glm::max(c0, s * 4), e = glm::min(c1, s * 4 + 3);
                for (int z = a.z; z <= e.z; ++z)
                    for (int y = a.y; y <= e.y; ++y)
                        for (int x = a.x; x <= e.x; ++x)
                            if (grid.cell({x, y, z}) != shared::CELL_EMPTY) return true;
            }
    return false;
}

}  // namespace engine::render
