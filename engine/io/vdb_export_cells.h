// ExportCells: the cells a VDB export reads (io/vdb_export.h), one region at a time — from a
// brick grid in memory, read in place, or from a region source (a world store, a terrain
// generator: world/region_source.h), which holds only the region being written. The export walks
// the world region by region (an OpenVDB Internal4 node of 128^3 voxels is exactly one region), so
// a world of any size is written with one region in memory beside the file.
#pragma once

#include <cstdint>
#include <optional>

#include "world/brick_grid.h"
#include "world/region_codec.h"
#include "world/region_source.h"

namespace engine::io {

class ExportCells {
public:
    explicit ExportCells(const world::BrickGrid& grid) : mGrid(&grid) {}
    explicit ExportCells(world::RegionSource& source) : mSource(&source) {}

    glm::ivec3 sizeInCells() const;
    bool containsCell(glm::ivec3 c) const;
    // The cell's encoding (world/brick_grid.h), CELL_EMPTY outside the world. From a source, the
    // region holding `c` is loaded if it is not the one held; a region that fails to load throws
    // ExportReadError (the exporter turns it into its error line).
    std::uint32_t cell(glm::ivec3 c);
    // The voxels of a brick cell just returned by cell().
    const world::BrickVoxels& brickVoxels(std::uint32_t cell) const;
    // Regions loaded so far (a region loaded again after another counts again).
    std::uint64_t regionLoads() const { return mLoads; }

private:
    const world::BrickGrid* mGrid = nullptr;
    world::RegionSource* mSource = nullptr;
    std::optional<world::RegionSnapshot> mRegion;  // the source's region held now
    std::uint64_t mLoads = 0;
};

// A region the source could not give (a damaged store row): its one-line message.
struct ExportReadError {
    std::string message;
};

}  // namespace engine::io
