// vox play's streaming (world/grid_streaming.h): which worlds stream and from what. A world
// streams from its store (a `.db`, or a scene file whose only generator is a `store` with the same
// palette) or from its terrain generator (a scene file whose only generator is `terrain`,
// generated region by region: world/terrain_region_source.h). Other worlds load whole.
//
// By default a world streams when it is wider than kStreamByDefaultVoxels along x or z: the
// 1024 x 256 x 1024 terrain loads whole in about a second, the 4096 x 256 x 4096 one needs 10 s
// and ~2 GiB, 8192 x 256 x 8192 4.4 GiB (docs/WORLD_STORE.md, "Streaming in vox play").
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include "core/error.h"
#include "scene/world_regions.h"
#include "world/grid_streaming.h"
#include "world/scene.h"

namespace game {

inline constexpr int kStreamByDefaultVoxels = engine::scene::kLoadWholeUpToVoxels;

struct StreamOptions {
    float radius = -1.0f;  // voxels; negative: stream by default at kDefaultRadius; 0: never
    std::uint64_t budgetMiB = 1536;     // the streamed regions' bytes in the grid, at most
    std::size_t regionsPerFrame = 4;    // copied into the grid per frame, at most
    std::size_t bricksPerFrame = 1024;  // their bricks per frame, at most (but one region)
    static constexpr float kDefaultRadius = 768.0f;
};

struct StreamedWorld {
    engine::world::Scene scene;   // its grid sized to the world and empty
    std::filesystem::path store;  // the store it streams from; empty for a generated terrain
    std::unique_ptr<engine::world::GridStreaming> streaming;
};

// Opens `path` for streaming when the options and the world say so; nullopt: load it whole. An
// explicit radius on a world that cannot stream is an error naming why.
engine::Result<std::optional<StreamedWorld>> openStreamedWorld(const std::filesystem::path& path,
                                                               const StreamOptions& options);

}  // namespace game
