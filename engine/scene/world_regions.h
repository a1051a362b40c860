// Where a world's voxels can be read one region at a time (world/region_source.h), without
// loading it whole: its region store (a `.db`, or a scene file whose only generator is a `store`
// with the same palette) or its terrain generator (a scene file whose only generator is
// `terrain`). vox play streams from it (game/streamed_world.h); vox export writes from it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/error.h"
#include "world/region_source.h"
#include "world/scene.h"

namespace engine::scene {

// Worlds up to this wide (x and z) load whole in vox play and export from memory: the 1024 x 256 x
// 1024 terrain loads in about a second; the 4096 x 256 x 4096 one needs 10 s and ~2 GiB
// (docs/WORLD_STORE.md). Wider ones stream, and a terrain exports region by region.
inline constexpr int kLoadWholeUpToVoxels = 2048;

// A world read without its voxels: its tables, its generators read but not run. Its grid is
// sized to the world and empty.
Result<world::Scene> loadWorldLean(const std::filesystem::path& path);

struct WorldRegions {
    std::unique_ptr<world::RegionSource> source;  // null: the world must be loaded whole
    std::filesystem::path store;                  // the store it reads; empty for a terrain
    std::string whyNot;                           // with no source: the reason, for messages
};

// The region source of `lean` (loaded from `path` by loadWorldLean). An error when the world names
// a store that cannot be read as it (another palette or size, a damaged file).
Result<WorldRegions> worldRegionsOf(const world::Scene& lean, const std::filesystem::path& path);

}  // namespace engine::scene
