// The largest worlds and objects the engine accepts, wherever they come from (scene files,
// VDB imports, the sandbox): checked on input so nothing downstream meets a size it cannot hold.
#pragma once

#include <cstdint>

namespace engine::world {

// Largest world: 2^25 top-grid cells (a 128 MiB top grid, the largest storage buffer lavapipe
// binds).
inline constexpr std::uint64_t kMaxTopGridCells = 1ull << 25;
inline constexpr int kMaxWorldExtent = 1 << 15;
// Largest dynamic object model per axis: it is re-voxelised every frame it moves.
inline constexpr int kMaxObjectExtent = 256;

}  // namespace engine::world
