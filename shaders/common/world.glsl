// World resources (set 0, bindings 0-4) and voxel/brick accessors. Layouts: shared/brick_grid.h.
// The dynamic grid (shared/dynamic_grid.h) is binding 4, read as texels like the static grid.
// The grid* accessors take a `dyn` flag that is a constant at every call site, so after
// inlining the compiler keeps one branch: the static path reads exactly what it always did.
#ifndef COMMON_WORLD_GLSL
#define COMMON_WORLD_GLSL

#extension GL_EXT_buffer_reference : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "shared/bindings.h"
#include "shared/brick_grid.h"
#include "shared/dynamic_grid.h"
#include "shared/material.h"
#include "shared/shader_features.h"

layout(buffer_reference, std430, buffer_reference_align = 4) readonly buffer BrickPage { uint words[]; };

layout(set = 0, binding = WORLD_BINDING_INFO, std430) readonly buffer WorldInfoBuffer { BrickGridInfo gWorld; };
// The super cells (skip distance per 4^3 cells, 0: occupied), the top grid's region table and
// cell pages, then every brick's mask words (see shared/brick_grid.h); and the page table (device
// address per brick page, as two uints). Both are read as texels: llvmpipe gathers a texel fetch for the 8
// lanes of a SIMD batch at once, where it compiles a storage-buffer read into a loop over the
// lanes with a branch per lane.
layout(set = 0, binding = WORLD_BINDING_CELLS) uniform usamplerBuffer gGridTexels;
layout(set = 0, binding = WORLD_BINDING_PAGES) uniform usamplerBuffer gPageTexels;
// The palette: three uvec4 texels per GpuMaterial (albedo, emission, flags). Every surface read
// (G-buffer loads, spatial taps, bounce hits) looks up its material at a lane-varying index.
layout(set = 0, binding = WORLD_BINDING_PALETTE) uniform usamplerBuffer gPaletteTexels;
// The dynamic grid: header, super cells, cells, masks, materials, object table (dynamic_grid.h),
// as texels for the same reason; bound always, read only when dynamicGridPresent().
layout(set = 0, binding = WORLD_BINDING_DYNAMIC) uniform usamplerBuffer gDynamicTexels;

vec3 materialAlbedo(uint material) { return uintBitsToFloat(texelFetch(gPaletteTexels, int(material) * 3).rgb); }
vec3 materialEmission(uint material) { return uintBitsToFloat(texelFetch(gPaletteTexels, int(material) * 3 + 1).rgb); }

// Where the super cells start among the grid texels: first.
uint superCellBase(ivec3 sizeInCells) { return 0u; }

uint boxVolume(ivec3 n) { return uint(n.x) * uint(n.y) * uint(n.z); }

// Where the region table starts among the grid texels: after the super cells.
uint regionTableBase(ivec3 sizeInCells) { return boxVolume((sizeInCells + 3) >> 2); }

// The grid texel where the top-grid page of the region holding `cell` starts (the region table's
// entry; regions without a page of their own read page 0, all empty). Everything from the size in
// cells, so a caller that read it once reads no more of the world info.
uint cellPageBase(ivec3 sizeInCells, ivec3 cell) {
    ivec3 n = (sizeInCells + int(PAGE_CELLS_AXIS - 1u)) >> int(REGION_CELLS_SHIFT);
    ivec3 r = cell >> int(REGION_CELLS_SHIFT);
    uint table = regionTableBase(sizeInCells);
    uint page = texelFetch(gGridTexels, int(table + uint(r.x) + uint(n.x) * (uint(r.y) + uint(n.y) * uint(r.z)))).x;
    return table + boxVolume(n) + page * PAGE_CELLS;
}

// A cell of the page that starts at texel `pageBase` (the cell's region's, cellPageBase).
uint pageCell(uint pageBase, ivec3 cell) {
    ivec3 l = cell & int(PAGE_CELLS_AXIS - 1u);
    return texelFetch(gGridTexels, int(pageBase + uint(l.x) + PAGE_CELLS_AXIS * (uint(l.y) + PAGE_CELLS_AXIS * uint(l.z)))).x;
}

// Where the bricks' mask words start among the grid texels: after the cell pages, whose number
// only the world info knows (brick b's BRICK_MASK_WORDS words at maskBase + b * BRICK_MASK_WORDS;
// a copy of its page's).
uint maskBase() { return gWorld.counts.w; }

uint worldCell(ivec3 cell) {
    ivec3 s = gWorld.sizeInCells.xyz;
    return pageCell(cellPageBase(s, cell), cell);
}

// The skip distance (shared/brick_grid.h; without the page bits).
uint worldSuperCell(ivec3 s) {
    ivec3 n = gWorld.sizeInSuperCells.xyz;
    uint i = uint(s.x) + uint(n.x) * (uint(s.y) + uint(n.y) * uint(s.z));
    return texelFetch(gGridTexels, int(i)).x & SUPER_SKIP_MASK;
}

uint64_t brickPageAddress(uint page) {
    uvec2 a = texelFetch(gPageTexels, int(page)).xy;
    return uint64_t(a.x) | (uint64_t(a.y) << 32);
}

uint brickMaskWord(uint brick, uint word) {
    BrickPage page = BrickPage(brickPageAddress(brick >> BRICK_PAGE_SHIFT));
    return page.words[(brick & (BRICK_PAGE_BRICKS - 1u)) * BRICK_MASK_WORDS + word];
}

uint brickMaterial(uint brick, uint voxelIndex) {
    BrickPage page = BrickPage(brickPageAddress(brick >> BRICK_PAGE_SHIFT));
    uint word = page.words[BRICK_PAGE_MATERIAL_OFFSET + (brick & (BRICK_PAGE_BRICKS - 1u)) * BRICK_MATERIAL_WORDS +
                           (voxelIndex >> 1u)];
    return (word >> ((voxelIndex & 1u) * 16u)) & 0xFFFFu;
}

// A scene without objects compiles the dynamic grid's code out (render/shader_features.h): lavapipe
// runs every traceScene's second traversal, loop and all, even when the flag below is 0 for all.
layout(constant_id = FEATURE_DYNAMIC_GRID) const bool kDynamicGrid = true;
bool dynamicGridPresent() { return kDynamicGrid && gWorld.dynamicGrid.x != 0u; }

uint dynamicTexel(uint i) { return texelFetch(gDynamicTexels, int(i)).x; }

ivec3 dynamicTexels3(uint i) { return ivec3(dynamicTexel(i), dynamicTexel(i + 1u), dynamicTexel(i + 2u)); }

// Only when dynamicGridPresent(): the object count and object i's bounds and motion.
uint dynamicObjectCount() { return dynamicTexel(3u); }  // header.origin.w

uint dynamicObjectBase(uint i) { return dynamicTexel(20u) + i * DYNAMIC_OBJECT_TEXELS; }  // header.objects.x

ivec3 dynamicObjectBoundsMin(uint i) { return dynamicTexels3(dynamicObjectBase(i)); }

ivec3 dynamicObjectBoundsMax(uint i) { return dynamicTexels3(dynamicObjectBase(i) + 4u); }

mat4 dynamicObjectPrevFromCurrent(uint i) {
    uint base = dynamicObjectBase(i) + 8u;
    mat4 m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = uintBitsToFloat(dynamicTexel(base + uint(4 * c + r)));
    return m;
}

// The dynamic grid's header, read once per traversal rather than at every step (private to the
// invocation; set by loadDynamicGrid before any dyn accessor below). Every ray of a scene with
// objects loads it (traceScene), so it takes eight texels, not 24: the other sizes follow from
// the size in cells by BrickGrid's rules, the super cells start right after the header, and the
// materials' offset is read at a hit (gridBrickMaterial). w components and objects stay 0.
DynamicGridHeader gDynHeader;
void loadDynamicGrid() {
    ivec3 cells = dynamicTexels3(4u);
    gDynHeader.origin = ivec4(dynamicTexels3(0u), 0);
    gDynHeader.sizeInCells = ivec4(cells, 0);
    gDynHeader.sizeInVoxels = ivec4(cells * int(BRICK_DIM), 0);
    gDynHeader.sizeInSuperCells = ivec4((cells + 3) / 4, 0);
    gDynHeader.offsets = uvec4(DYNAMIC_HEADER_TEXELS, dynamicTexel(17u), dynamicTexel(18u), 0u);
    gDynHeader.objects = uvec4(0u);
}

// The same accessors over either grid (grid-local coordinates).
ivec3 gridSizeInVoxels(bool dyn) {
    if (dyn) return gDynHeader.sizeInVoxels.xyz;
    return gWorld.sizeInVoxels.xyz;
}

ivec3 gridSizeInSuperCells(bool dyn) {
    if (dyn) return gDynHeader.sizeInSuperCells.xyz;
    return gWorld.sizeInSuperCells.xyz;
}

ivec3 gridSizeInCells(bool dyn) {
    if (dyn) return gDynHeader.sizeInCells.xyz;
    return gWorld.sizeInCells.xyz;
}

// Super-cell and cell reads for a caller that read the grid's size `n` once, before its loop:
// llvmpipe turns a buffer read into a loop over the SIMD lanes (in Mesa 21.3's source even one
// whose address all lanes share), so a size read per step can cost as much as the cell read.
// `base`: superCellBase of the static grid's size in cells (unused for the dynamic grid).
// The static grid's occupied super cells carry their page (SUPER_PAGE_SHIFT): mask with
// SUPER_SKIP_MASK for the skip distance.
uint gridSuperCellIn(bool dyn, ivec3 n, uint base, ivec3 s) {
    uint i = uint(s.x) + uint(n.x) * (uint(s.y) + uint(n.y) * uint(s.z));
    if (dyn) return dynamicTexel(gDynHeader.offsets.x + i);
    return texelFetch(gGridTexels, int(base + i)).x;
}

// The static grid's cells go through the region table (two texel fetches); the dynamic grid's
// top grid is dense.
uint gridCellIn(bool dyn, ivec3 n, ivec3 cell) {
    if (dyn) {
        uint i = uint(cell.x) + uint(n.x) * (uint(cell.y) + uint(n.y) * uint(cell.z));
        return dynamicTexel(gDynHeader.offsets.y + i);
    }
    return pageCell(cellPageBase(n, cell), cell);
}

// The texel where top-grid page `page` starts (pages follow the region table).
uint pageBaseOf(ivec3 sizeInCells, uint page) {
    ivec3 n = (sizeInCells + int(PAGE_CELLS_AXIS - 1u)) >> int(REGION_CELLS_SHIFT);
    return regionTableBase(sizeInCells) + boxVolume(n) + page * PAGE_CELLS;
}

// The skip distance.
uint gridSuperCell(bool dyn, ivec3 s) {
    return gridSuperCellIn(dyn, gridSizeInSuperCells(dyn), dyn ? 0u : superCellBase(gWorld.sizeInCells.xyz), s) &
           SUPER_SKIP_MASK;
}

uint gridCell(bool dyn, ivec3 cell) { return gridCellIn(dyn, gridSizeInCells(dyn), cell); }

// The first mask word of a brick, as an index for gridMaskWordAt; `base` is maskBase of the
// static grid's sizes (unused for the dynamic grid).
uint gridBrickMaskIndex(bool dyn, uint base, uint brick) {
    if (dyn) return gDynHeader.offsets.z + brick * BRICK_MASK_WORDS;
    return base + brick * BRICK_MASK_WORDS;
}

uint gridMaskWordAt(bool dyn, uint index) {
    if (dyn) return dynamicTexel(index);
    return texelFetch(gGridTexels, int(index)).x;
}

uint gridMaskWord(bool dyn, uint brick, uint word) {
    if (dyn) {
        return dynamicTexel(gDynHeader.offsets.z + brick * BRICK_MASK_WORDS + word);
    }
    return brickMaskWord(brick, word);
}

uint gridBrickMaterial(bool dyn, uint brick, uint voxelIndex) {
    if (dyn) {
        uint w = dynamicTexel(dynamicTexel(19u) + brick * BRICK_MATERIAL_WORDS + (voxelIndex >> 1u));  // header.offsets.w
        return (w >> ((voxelIndex & 1u) * 16u)) & 0xFFFFu;
    }
    return brickMaterial(brick, voxelIndex);
}

// Material of a grid-local voxel, 0 = empty or outside.
uint gridVoxelMaterial(bool dyn, ivec3 v) {
    if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, gridSizeInVoxels(dyn)))) return 0u;
    uint cell = gridCell(dyn, v >> 3);
    if (cell == CELL_EMPTY) return 0u;
    if ((cell & CELL_HOMOGENEOUS) != 0u) return cell & CELL_MATERIAL_MASK;
    ivec3 l = v & 7;
    return gridBrickMaterial(dyn, cell - 1u, uint(l.x + 8 * l.y + 64 * l.z));
}

// Whether a grid-local voxel is solid (outside: no), from the occupancy masks: the same answer
// as gridVoxelMaterial(dyn, v) != 0u, but all texel fetches, where a static brick's material is a
// page-table fetch and a device-address read (a loop over the SIMD lanes on llvmpipe). For
// callers that ask many voxels per pixel (the cache's exposure, level-of-detail and fallback tests).
bool gridVoxelSolid(bool dyn, ivec3 v) {
    ivec3 size = gridSizeInVoxels(dyn);
    if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, size))) return false;
    ivec3 cells = gridSizeInCells(dyn);
    uint cell = gridCellIn(dyn, cells, v >> 3);
    if (cell == CELL_EMPTY) return false;
    if ((cell & CELL_HOMOGENEOUS) != 0u) return true;
    ivec3 l = v & 7;
    uint bit = uint(l.x + 8 * l.y + 64 * l.z);
    uint first = gridBrickMaskIndex(dyn, dyn ? 0u : maskBase(), cell - 1u);
    return ((gridMaskWordAt(dyn, first + (bit >> 5u)) >> (bit & 31u)) & 1u) != 0u;
}

ivec3 faceNormal(uint face) {
    ivec3 n = ivec3(0);
    if (face < 6u) n[face >> 1u] = (face & 1u) != 0u ? 1 : -1;
    return n;
}

#endif
