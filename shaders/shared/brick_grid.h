// Two-level brick grid as the GPU sees it (and the CPU stores it — same layout).
//
// Super grid: one uint per 4^3 cells (32^3 voxels), so rays cross open air 32 voxels at a step:
//   0       the super cell holds a non-empty cell
//   k >= 1  empty, and so is every super cell within Chebyshev distance k - 1 of it (k is capped
//           at SUPER_SKIP_MAX): a ray walks that box without reading the grid again.
// It follows BrickGridInfo in the same buffer.
// Top grid: one uint per 8^3 cell, x fastest:
//   0                         empty cell
//   CELL_HOMOGENEOUS | mat    every voxel of the cell is material `mat` (no brick storage)
//   brickIndex + 1            index into the brick pool
// Brick pool: split into pages of BRICK_PAGE_BRICKS bricks so no single buffer exceeds
// lavapipe's 128 MiB maxStorageBufferRange; shaders reach pages by buffer device address.
// One page = [masks of all its bricks][materials of all its bricks].
#ifndef SHARED_BRICK_GRID_H
#define SHARED_BRICK_GRID_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint BRICK_DIM = 8u;
SHARED_CONST uint BRICK_SHIFT = 3u;
SHARED_CONST uint BRICK_VOXELS = 512u;
SHARED_CONST uint SUPER_SHIFT = 5u;  // a super cell spans 32 voxels = 4 cells per axis
SHARED_CONST uint SUPER_SKIP_MAX = 4u;  // largest skip distance kept (an edit rewrites (2*4-1)^3 super cells at most)
SHARED_CONST uint CELL_EMPTY = 0u;
SHARED_CONST uint CELL_HOMOGENEOUS = 0x80000000u;
SHARED_CONST uint CELL_MATERIAL_MASK = 0xFFFFu;

// Occupancy masks of one brick, coarsest last. Voxel (x,y,z) in 0..7 is bit x+8y+64z of the
// 512-bit fine mask; 2^3 block (x,y,z)/2 is bit of the 64-bit coarse mask; 4^3 block is a
// bit of the 8-bit quarter mask. A set bit means "something solid in there".
SHARED_CONST uint MASK_FINE_WORDS = 16u;
SHARED_CONST uint MASK_COARSE_WORD = 16u;  // 2 words: 16, 17
SHARED_CONST uint MASK_QUARTER_WORD = 18u;
SHARED_CONST uint BRICK_MASK_WORDS = 20u;  // padded to a multiple of 4 words
SHARED_CONST uint BRICK_MATERIAL_WORDS = 256u;  // 512 uint16 ids, two per word, x fastest

SHARED_CONST uint BRICK_PAGE_SHIFT = 12u;
SHARED_CONST uint BRICK_PAGE_BRICKS = 4096u;  // 1 << BRICK_PAGE_SHIFT
SHARED_CONST uint BRICK_PAGE_MATERIAL_OFFSET = BRICK_PAGE_BRICKS * BRICK_MASK_WORDS;  // words
SHARED_CONST uint BRICK_PAGE_WORDS = BRICK_PAGE_BRICKS * (BRICK_MASK_WORDS + BRICK_MATERIAL_WORDS);

// Faces are named by their outward normal: 0 -X, 1 +X, 2 -Y, 3 +Y, 4 -Z, 5 +Z.
SHARED_CONST uint FACE_NEG_X = 0u;
SHARED_CONST uint FACE_POS_Y = 3u;
SHARED_CONST uint FACE_INSIDE = 6u;  // the ray started inside a solid voxel
SHARED_CONST uint FACE_NONE = 7u;    // no hit

SHARED_CONST uint TRAVERSAL_MAX_STEPS = 16384u;

struct BrickGridInfo {
    ivec4 sizeInCells;   // xyz: top-grid size in cells, w unused
    ivec4 sizeInVoxels;  // xyz: sizeInCells * 8
    ivec4 sizeInSuperCells;  // xyz: ceil(sizeInCells / 4)
    uvec4 counts;        // x: allocated bricks, y: pages, z: materials, w: unused
    uvec4 dynamicGrid;   // x: 1 when the scene has a dynamic grid (world binding 4, dynamic_grid.h), else 0; yzw unused
};
SHARED_ASSERT_SIZE(BrickGridInfo, 80);

SHARED_END

#endif
