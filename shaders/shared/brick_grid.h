// Two-level brick grid as the GPU sees it (and the CPU stores it — same layout).
//
// Super grid: one uint per 4^3 cells (32^3 voxels), so rays cross open air 32 voxels at a step:
//   0       the super cell holds a non-empty cell
//   k >= 1  empty, and so is every super cell within Chebyshev distance k - 1 of it (k is capped
//           at SUPER_SKIP_MAX): a ray walks that box without reading the grid again.
// On the GPU an occupied super cell of the static world also names its region's top-grid page
// (below): page << SUPER_PAGE_SHIFT, the low bits 0. The traversal reads the super cell before
// any of its cells, so it finds the page with no read of the region table.
// Top grid: one uint per 8^3 cell:
//   0                         empty cell
//   CELL_HOMOGENEOUS | mat    every voxel of the cell is material `mat` (no brick storage)
//   brickIndex + 1            index into the brick pool
// paged by region (engine/world/paged_top_grid.h): a region table holds, per region of
// REGION_CELLS^3 cells (x fastest), the number of its page of PAGE_CELLS cells (x fastest within
// the region); page 0 is all empty and shared by every region without a non-empty cell.
// The grid texels (world binding 1) are: the super cells, the region table, the cell pages, then
// a copy of every brick slot's mask words. The first three start where their sizes say (from the
// size in cells); the masks' start is BrickGridInfo::counts.w.
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
SHARED_CONST uint SUPER_SHIFT = 5u;       // a super cell spans 32 voxels = 4 cells per axis
SHARED_CONST uint SUPER_SKIP_MASK = 7u;   // the skip distance's bits of a GPU super cell
SHARED_CONST uint SUPER_PAGE_SHIFT = 3u;  // an occupied GPU super cell: its region's page << 3
SHARED_CONST uint SUPER_SKIP_MAX =
    4u;  // largest skip distance kept (an edit rewrites (2*4-1)^3 super cells at most)
SHARED_CONST uint CELL_EMPTY = 0u;
SHARED_CONST uint CELL_HOMOGENEOUS = 0x80000000u;
SHARED_CONST uint CELL_MATERIAL_MASK = 0xFFFFu;
SHARED_CONST uint REGION_CELLS_SHIFT = 4u;  // a region is 16^3 cells (world/region.h)
SHARED_CONST uint PAGE_CELLS_AXIS = 16u;    // 1 << REGION_CELLS_SHIFT
SHARED_CONST uint PAGE_CELLS = 4096u;       // cells per top-grid page: one region's

// Occupancy masks of one brick, coarsest last. Voxel (x,y,z) in 0..7 is bit x+8y+64z of the
// 512-bit fine mask; 2^3 block (x,y,z)/2 is bit of the 64-bit coarse mask; 4^3 block is a
// bit of the 8-bit quarter mask. A set bit means "something solid in there".
SHARED_CONST uint MASK_FINE_WORDS = 16u;
SHARED_CONST uint MASK_COARSE_WORD = 16u;  // 2 words: 16, 17
SHARED_CONST uint MASK_QUARTER_WORD = 18u;
SHARED_CONST uint BRICK_MASK_WORDS = 20u;       // padded to a multiple of 4 words
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
    ivec4 sizeInCells;       // xyz: top-grid size in cells, w unused
    ivec4 sizeInVoxels;      // xyz: sizeInCells * 8
    ivec4 sizeInSuperCells;  // xyz: ceil(sizeInCells / 4)
    uvec4 counts;       // x: allocated bricks, y: brick pages, z: materials, w: first mask texel
    uvec4 dynamicGrid;  // x: 1 when the scene has a dynamic grid (world binding 4, dynamic_grid.h),
                        // else 0; yzw unused
};
SHARED_ASSERT_SIZE(BrickGridInfo, 80);

SHARED_END

#endif
