// Brick payload (.bricks): a BrickGrid's voxels as they sit in memory — the top grid, then
// every live brick once, then a checksum. The sandbox's saves reference it from their scene
// file (`[[generator]] type = "bricks"`). It stands in for the .vdb payload until the OpenVDB
// exporter exists; a truncated or corrupt file is reported, never half-loaded.
#pragma once

#include <filesystem>

#include "core/error.h"
#include "world/brick_grid.h"

namespace engine::io {

// Writes to `path` directly; callers wanting atomicity wrap it in writeAtomically.
Status writeBrickPayload(const std::filesystem::path& path, const world::BrickGrid& grid);
Result<world::BrickGrid> readBrickPayload(const std::filesystem::path& path);

}  // namespace engine::io
