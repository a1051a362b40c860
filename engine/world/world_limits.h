// The largest worlds and objects the engine accepts, wherever they come from (scene files,
// VDB imports, the sandbox): checked on input so nothing downstream meets a size it cannot hold.
#pragma once

#include <cstdint>

namespace engine::world {

// Largest world an importer (VDB, .vox) builds whole in memory: 2^25 top-grid cells.
inline constexpr std::uint64_t kMaxTopGridCells = 1ull << 25;
// Largest world a scene file describes: 2^30 top-grid cells (32768 x 512 x 32768 voxels). The
// top grid is paged (world/paged_top_grid.h), so its memory follows content; what stays sized to
// the world is the super grid (4 + 2 bytes per 4^3 cells on the CPU, 4 on the GPU: 96 + 64 MiB
// here) and cell indices, which are uint32. Such a world is meant to be streamed (vox play).
inline constexpr std::uint64_t kMaxSceneTopGridCells = 1ull << 30;
inline constexpr int kMaxWorldExtent = 1 << 15;
// Largest dynamic object model per axis: it is re-voxelised every frame it moves.
inline constexpr int kMaxObjectExtent = 256;

}  // namespace engine::world
