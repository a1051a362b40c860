// OpenVDB export: one .vdb per world (layout in io/vdb_layout.h and docs/VDB.md).
//
// Streamed: no OpenVDB tree is built. Each grid's topology and leaf values are generated from the
// brick grid cell by cell as the file is written (a homogeneous cell becomes one 8^3 tile, an
// empty cell nothing, a brick one leaf), so exporting holds one leaf of values beyond the world —
// and, from a region source, one region instead of the world (io/vdb_export_cells.h).
// The save is atomic (core/atomic_file.h): a temporary file beside the target, every write
// checked, fsynced, then renamed, so a failed export leaves the previous file intact.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "world/region_source.h"
#include "world/scene.h"

namespace engine::io {

struct VdbExportOptions {
    // Also write the albedo and emission grids (for other tools; import does not need them).
    bool colourGrids = true;
    // Also write a float fog volume `density`, 1.0 in every solid voxel, first in the file: the
    // grid Blender (Volume to Mesh, its viewport), vdb_render and pyopenvdb (which cannot read
    // int32 grids) work with. Import ignores it.
    bool densityGrid = false;
    // Turn the grids' transform so +z is up (Blender); index space stays ours (vdb_layout.h).
    bool zUp = false;
};

// Export settings for another tool, by name: "blender" (Z-up, density grid), "houdini" (Y-up,
// density grid); an Error for an unknown name.
Result<VdbExportOptions> vdbExportOptionsFor(const std::string& tool);

struct VdbExportReport {
    std::vector<std::string> grids;
    std::uint64_t solidVoxels = 0;
    std::uint64_t tiles = 0;   // homogeneous cells written as one tile each
    std::uint64_t leaves = 0;  // bricks written as 8^3 leaves
    std::uint64_t fileBytes = 0;
    std::uint64_t regionLoads = 0;  // regions read from a source (each grid reads each three times)
};

Status exportVdb(const world::Scene& scene, const std::filesystem::path& path,
                 const VdbExportOptions& options = {}, VdbExportReport* report = nullptr);
// The same file, the voxels read from `source` one region at a time (a world store, a streamed
// terrain): the export holds one region, never the world. `scene` gives everything else (palette,
// cameras, sky, voxel size); its grid is not read, but its size must be the source's.
Status exportVdb(const world::Scene& scene, world::RegionSource& source,
                 const std::filesystem::path& path, const VdbExportOptions& options = {},
                 VdbExportReport* report = nullptr);

}  // namespace engine::io
