// World generators used by scene files. All are deterministic functions of their parameters
// (seeded noise, seeded placement) and write through BrickGrid's cell API, so large worlds
// are built brick by brick and uniform regions never allocate brick storage.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "world/brick_grid.h"
#include "world/height_field.h"

namespace engine::world {

struct TerrainParams {
    MaterialId top = kEmpty;   // the surface voxel of each column
    MaterialId soil = kEmpty;  // soilDepth voxels under it
    MaterialId rock = kEmpty;  // everything below
    int soilDepth = 3;
    float baseHeight = 32.0f;
    float amplitude = 16.0f;
    float wavelength = 96.0f;  // voxels per period of the first octave
    int octaves = 4;
    std::uint32_t seed = 1;
};
// Height field terrain over the whole grid footprint.
void generateTerrain(BrickGrid& grid, const TerrainParams& p);
// The terrain's column height (first empty y) at (x, z), without looking at the grid.
int terrainHeight(const TerrainParams& p, int x, int z);
// The terrain's column materials (for a region generated alone: world/terrain_region_source.h).
ColumnMaterials terrainColumns(const TerrainParams& p);

struct CornellParams {
    glm::ivec3 origin{0};
    int interior = 256;    // inner edge length in voxels, a multiple of 8
    int wall = 8;          // wall thickness
    int lightBricks = 16;  // the ceiling light is lightBricks x lightBricks emissive 8^3 bricks
    MaterialId white = kEmpty, red = kEmpty, green = kEmpty, light = kEmpty;
};
// Cornell box of the thesis §3.2: open at -Z, red wall at +X (left when looking in), green at -X,
// two white blocks, a ceiling light of lightBricks^2 brick-aligned emissive bricks hanging under
// the ceiling.
void generateCornellBox(BrickGrid& grid, const CornellParams& p);

struct BuildingsParams {
    int count = 6;
    std::uint32_t seed = 2;
    glm::ivec2 minSize{12, 12}, maxSize{28, 28};
    int minHeight = 10, maxHeight = 30;
    MaterialId wall = kEmpty, roof = kEmpty, window = kEmpty;
    int margin = 8;  // keep away from the world's edge
};
// Hollow buildings with window rows and a door, standing on whatever ground is below them.
void generateBuildings(BrickGrid& grid, const BuildingsParams& p);

struct LampsParams {
    int count = 10;
    std::uint32_t seed = 3;
    int postHeight = 4;
    int lampSize = 2;
    MaterialId post = kEmpty, light = kEmpty;
    int margin = 4;
};
// Lamp posts with an emissive block on top, on the ground.
void generateLamps(BrickGrid& grid, const LampsParams& p);

// First empty y above the highest solid voxel of column (x, z); 0 for an empty column.
int groundHeight(const BrickGrid& grid, int x, int z);

}  // namespace engine::world
