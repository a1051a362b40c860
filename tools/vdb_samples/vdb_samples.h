// Foreign .vdb files for tests, fuzz seeds and measurements, written with OpenVDB's own API (not
// with our exporter) the way Houdini, Blender or a simulation would write them. Each function
// documents exactly what it writes, so tests can compare against the analytic answer.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <string>

namespace vox::samples {

namespace fs = std::filesystem;

// A narrow-band level-set sphere (OpenVDB's createLevelSetSphere): radius in voxels, centre in
// voxels, half width 3 voxels. Grid "surface", class level set.
void writeLevelSetSphere(const fs::path& path, float radiusVoxels,
                         glm::vec3 centreVoxels = glm::vec3(0.0f), double voxelSize = 1.0);

// Fog volume "density": density 1 inside [min, max) (index space), 0.25 on a one-voxel shell
// around it (below the default threshold), inactive elsewhere. Large boxes are stored as tiles.
void writeFogBox(const fs::path& path, glm::ivec3 min, glm::ivec3 max, double voxelSize = 1.0);

// vec3s grid "Cd": active over [0, n)^3 with colour (x, y, z) / (n - 1), a smooth gradient with n^3
// distinct colours.
void writeColourGradient(const fs::path& path, int n);
// vec3s grid "Cd": [0, 12)^3 split in 6 slabs along x, each one of six fixed colours.
void writeColourSlabs(const fs::path& path);
// The six colours of writeColourSlabs, slab i covering x in [2i, 2i+2).
glm::vec3 slabColour(int i);

// Level-set sphere (radius 10, centre 0) "surface" plus a vec3s "Cd" grid, red for x < 0 and blue
// for x >= 0, over the same voxels.
void writeLevelSetWithColour(const fs::path& path);

// A Z-up fog "tower" like Blender writes: a 4x4 column from z = 0 to 32 with an 12x12x2 cap at
// z = [30, 32), centred on the column. File metadata "creator" = creator (empty: none).
void writeZUpTower(const fs::path& path, const std::string& creator);

// A Blender 2.8+ fluid cache frame as Mantaflow writes it: no file metadata at all, the tower of
// writeZUpTower as "density". With gridMetadata, every grid carries Mantaflow's
// file_base_resolution (vec3i) and file_voxel_size (float); without, the file only has the grid
// names of Blender's smoke cache to go by: an empty "shadow" grid beside "density".
void writeMantaflowTower(const fs::path& path, bool gridMetadata);

// Grid instancing: "density", a fog volume of 1.0 over [0,30) x [0,30) x [0,1) (900 voxels), and
// "density_copy", a second grid sharing its tree, which OpenVDB writes as an instance (no tree of
// its own, block offset 0) -- as pyopenvdb does for `h = g.copy()`.
void writeGridInstances(const fs::path& path);

// Two float fog grids with the same name "density": the first 1.0 over [0,2)^3 (8 voxels), the
// second 1.0 over [0,3)^3 (27 voxels). OpenVDB 10 stores them as "density\x1e0" and
// "density\x1e1" (vox info shows "density[0]", "density[1]"; vdb_print "density" twice).
void writeDuplicateNames(const fs::path& path);

// Fog volume "density" of 1.0 over [0,n)^3 stored as tiles only (no leaves) when n is a
// multiple of 128: a few hundred bytes for any size.
void writeFogCube(const fs::path& path, int n);
// The same as a mask grid "mask" (tiles only): imports without a single brick.
void writeMaskCube(const fs::path& path, int n);

// Int32 grid "labels": values 7 and 42 in two 8^3 blocks, and -3 in one voxel.
void writeIdGrid(const fs::path& path);

// Unusable grids only: a vec3i grid "flow" and an empty float grid "density".
void writeWrongTypes(const fs::path& path);
// One float grid "density" with no active voxels.
void writeEmptyGrid(const fs::path& path);
// A fog box whose transform is rotated 30 degrees about y.
void writeRotatedGrid(const fs::path& path);
// A fog box with a frustum (perspective) transform.
void writeFrustumGrid(const fs::path& path);
// A fog box of 20^3 voxels with voxel size 0.5 x 0.5 x 1.0.
void writeNonUniformGrid(const fs::path& path);
// A fog volume with one active root-level tile: 4096^3 voxels of density 1.
void writeGiantTile(const fs::path& path);

// Every sample above at small sizes, plus a voxengine world export, into dir (the fuzz seeds).
void writeSeedCorpus(const fs::path& dir);

}  // namespace vox::samples
