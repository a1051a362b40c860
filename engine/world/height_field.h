// Filling a grid from a height field, brick by brick: the shared back end of the terrain and
// mountain generators. Cells wholly below the surface layers become homogeneous rock (no brick
// storage); only cells the surface passes through get a brick.
#pragma once

#include <functional>

#include "world/brick_grid.h"

namespace engine::world {

struct ColumnMaterials {
    MaterialId top = kEmpty;   // the surface voxel of each column
    MaterialId soil = kEmpty;  // soilDepth voxels under it
    MaterialId rock = kEmpty;  // everything below
    int soilDepth = 3;
    // Optional: surface voxels at or above snowLine become `snow`; where the surface steps by
    // more than `cliffStep` voxels to a neighbour, top and soil become `cliff` (bare rock faces).
    MaterialId snow = kEmpty;
    int snowLine = 1 << 30;
    MaterialId cliff = kEmpty;
    int cliffStep = 1 << 30;
};

// heightAt(x, z) is the first empty y of column (x, z) (0 = an empty column). Columns cover the
// grid's whole footprint.
void fillHeightField(BrickGrid& grid, const std::function<int(int, int)>& heightAt,
                     const ColumnMaterials& m);
// The same over a grid that stands for the world's cells from `originCell` on (one region, built
// alone by a region loader): heightAt still takes world columns, and each cell is written exactly
// as the whole-world fill writes it. `progress` reports to core/progress.h.
void fillHeightFieldAt(BrickGrid& grid, const std::function<int(int, int)>& heightAt,
                       const ColumnMaterials& m, glm::ivec3 originCell, bool progress = false);

}  // namespace engine::world
