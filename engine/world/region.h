// Regions: the unit a world is stored in (world/region_store.h) and saved by (an edit marks its
// region; a save writes only the marked ones). A region is a cube of kRegionCells^3 top-grid
// cells (kRegionCells * 8 voxels a side), clipped at the world's edge; its key is its position in
// region units. The size was chosen by measurement (docs/WORLD_STORE.md, "Region size").
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "world/brick.h"

namespace engine::world {

inline constexpr int kRegionCellsShift = 4;
inline constexpr int kRegionCells = 1 << kRegionCellsShift;  // 16 cells = 128 voxels a side

struct RegionKey {
    int x = 0, y = 0, z = 0;
    auto operator<=>(const RegionKey&) const = default;
    glm::ivec3 vec() const { return {x, y, z}; }
};

// Regions along each axis of a grid of `sizeInCells` cells, for regions of `regionCells` cells.
inline glm::ivec3 regionCount(glm::ivec3 sizeInCells, int regionCells = kRegionCells) {
    return (sizeInCells + (regionCells - 1)) / regionCells;
}
inline RegionKey regionOfCell(glm::ivec3 cell, int regionCells = kRegionCells) {
    const glm::ivec3 r = cell / regionCells;
    return {r.x, r.y, r.z};
}
// The region's cells, min inclusive and max exclusive, clipped to the grid.
struct CellRange {
    glm::ivec3 min{0};
    glm::ivec3 max{0};
    glm::ivec3 size() const { return max - min; }
    std::size_t count() const {
        const glm::ivec3 s = size();
        return std::size_t(s.x) * std::size_t(s.y) * std::size_t(s.z);
    }
};
inline CellRange regionCells(RegionKey key, glm::ivec3 sizeInCells,
                             int regionCells = kRegionCells) {
    const glm::ivec3 lo = key.vec() * regionCells;
    return {lo, glm::min(lo + regionCells, sizeInCells)};
}

}  // namespace engine::world
