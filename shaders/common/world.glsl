// World resources (set 0, bindings 0-3) and voxel/brick accessors. Layouts: shared/brick_grid.h.
#ifndef COMMON_WORLD_GLSL
#define COMMON_WORLD_GLSL

#extension GL_EXT_buffer_reference : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "shared/bindings.h"
#include "shared/brick_grid.h"
#include "shared/material.h"

layout(buffer_reference, std430, buffer_reference_align = 4) readonly buffer BrickPage { uint words[]; };

layout(set = 0, binding = WORLD_BINDING_INFO, std430) readonly buffer WorldInfoBuffer {
    BrickGridInfo gWorld;
    uint gSuperCells[];  // non-empty cells per 4^3 cells
};
layout(set = 0, binding = WORLD_BINDING_CELLS, std430) readonly buffer CellBuffer { uint gCells[]; };
layout(set = 0, binding = WORLD_BINDING_PAGES, std430) readonly buffer PageTable { uint64_t gPages[]; };
layout(set = 0, binding = WORLD_BINDING_PALETTE, std430) readonly buffer PaletteBuffer { GpuMaterial gMaterials[]; };

uint worldCell(ivec3 cell) {
    ivec3 s = gWorld.sizeInCells.xyz;
    return gCells[uint(cell.x) + uint(s.x) * (uint(cell.y) + uint(s.y) * uint(cell.z))];
}

uint worldSuperCell(ivec3 s) {
    ivec3 n = gWorld.sizeInSuperCells.xyz;
    return gSuperCells[uint(s.x) + uint(n.x) * (uint(s.y) + uint(n.y) * uint(s.z))];
}

uint brickMaskWord(uint brick, uint word) {
    BrickPage page = BrickPage(gPages[brick >> BRICK_PAGE_SHIFT]);
    return page.words[(brick & (BRICK_PAGE_BRICKS - 1u)) * BRICK_MASK_WORDS + word];
}

uint brickMaterial(uint brick, uint voxelIndex) {
    BrickPage page = BrickPage(gPages[brick >> BRICK_PAGE_SHIFT]);
    uint word = page.words[BRICK_PAGE_MATERIAL_OFFSET + (brick & (BRICK_PAGE_BRICKS - 1u)) * BRICK_MATERIAL_WORDS +
                           (voxelIndex >> 1u)];
    return (word >> ((voxelIndex & 1u) * 16u)) & 0xFFFFu;
}

ivec3 faceNormal(uint face) {
    ivec3 n = ivec3(0);
    if (face < 6u) n[face >> 1u] = (face & 1u) != 0u ? 1 : -1;
    return n;
}

#endif
