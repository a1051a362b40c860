// A region's voxels as bytes, and back: what one row of the region store holds
// (world/region_store.h). A snapshot is a plain copy of the region's cells and bricks, taken in
// the frame (cheap: a memcpy of what the region holds); encoding compresses it with zstd, off the
// frame (a save's worker). Decoding checks every size and id against the header and the palette,
// so a damaged or hostile row gives one error line, never a crash or a broken grid.
//
// Payload (little-endian, then one zstd frame over all of it):
//   u32 magic "VXRG", u32 version (1), u32 size in cells x, y, z, u32 brick count B,
//   u32 cell[x * y * z]   (x fastest; 0 empty, 0x80000000|material homogeneous,
//                          k in 1..B: the k-th brick, numbered in cell order)
//   u16 voxel[B * 512]    (each brick's material ids, x fastest as in world/brick.h)
// Cell encodings round-trip exactly, so a world read back equals the one written (BrickGrid ==).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/error.h"
#include "world/brick_grid.h"
#include "world/region.h"

namespace engine::world {

struct RegionSnapshot {
    RegionKey key;
    glm::ivec3 size{0};                // cells (the region clipped to the world)
    std::vector<std::uint32_t> cells;  // encoded as in the payload above
    std::vector<BrickVoxels> bricks;
    bool empty() const;  // every cell empty: the store keeps no row for it
};

// Copies the region's cells and bricks out of the grid.
RegionSnapshot snapshotRegion(const BrickGrid& grid, RegionKey key,
                              int regionCellCount = kRegionCells);
// Writes the snapshot's cells into `grid`, shifted by -cellOffset (a box export reads regions into
// a grid that starts at cellOffset); cells outside the grid are skipped.
void writeRegion(const RegionSnapshot& region, BrickGrid& grid, int regionCellCount = kRegionCells,
                 glm::ivec3 cellOffset = glm::ivec3(0));

// Empties the region's cells in `grid`, its bricks back to the pool (a streamed region that
// leaves: world/grid_streaming.h).
void eraseRegion(BrickGrid& grid, RegionKey key, int regionCellCount = kRegionCells);

struct EncodedRegion {
    RegionKey key;
    std::uint64_t rawBytes = 0;  // the payload before compression
    std::vector<std::uint8_t> blob;
};

// zstd level 3 by default: docs/WORLD_STORE.md has the measured sizes and times of other levels.
EncodedRegion encodeRegion(const RegionSnapshot& region, int zstdLevel = 3);
// `expectedSize`: the region's size in cells for the store's world; `paletteSize`: ids must be
// below it. `where` names the row in messages ("w.db: region (1, 0, 2)").
Result<RegionSnapshot> decodeRegion(RegionKey key, std::span<const std::uint8_t> blob,
                                    glm::ivec3 expectedSize, std::size_t paletteSize,
                                    const std::string& where);

}  // namespace engine::world
