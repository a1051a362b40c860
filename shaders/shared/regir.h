// ReGIR, world-space light candidates (Boksansky, Jukarainen & Wyman, "Rendering many lights with
// grid-based reservoirs", Ray Tracing Gems II ch. 23; NVIDIA RTXDI): a grid of cells over the
// world, each holding REGIR_CELL_ENTRIES light samples resampled every frame from power-drawn
// candidates with a target that favours lights near the cell. A pixel draws its ReSTIR/RIS
// candidates from the entries of the cell its surface lies in; each entry carries its RIS
// contribution weight, the pixel's candidate weight is target x that weight (RIS inside RIS), so
// the estimators stay unbiased. Packed on the host by engine/render/regir/regir_grid.h.
#ifndef SHARED_REGIR_H
#define SHARED_REGIR_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint REGIR_CELL_ENTRIES = 32u;   // light samples per cell
SHARED_CONST uint REGIR_MAX_CELLS = 4096u;    // the cell size grows until the world fits in this many
SHARED_CONST uint REGIR_GROUP_SIZE = 64u;

// The ReGIR knobs as the host keeps them (lighting::LightingSettings::regir, with these defaults);
// lighting/lighting_knobs.cpp gives each its name, range and help. Switch `enabled` is set by
// `--sampling regir`.
struct RegirKnobs {
    uint enabled SHARED_INIT(0u);             // ReSTIR/RIS candidates from the grid (else sampling by power or uniform)
    float cellSize SHARED_INIT(16.0f);        // voxels (smallest; grown to fit REGIR_MAX_CELLS)
    uint buildCandidates SHARED_INIT(8u);     // power-drawn candidates resampled into each cell entry
    uint pad0 SHARED_INIT(0u);
    SHARED_EQUALITY(RegirKnobs)
};
SHARED_ASSERT_SIZE(RegirKnobs, 16);

// Where the grid lies and this frame's randomness; the header of the grid buffer.
struct RegirGridInfo {
    vec4 origin;   // xyz: world position of cell (0,0,0)'s low corner (voxels); w: cell size (voxels)
    uvec4 dims;    // xyz: cells per axis; w: cells in all
    uvec4 build;   // x: candidates per entry, y: frame index, z: seed, w: unused
};
SHARED_ASSERT_SIZE(RegirGridInfo, 48);

// One light sample of a cell: the emitter slot (RESERVOIR_EMPTY: no lights) and its contribution
// weight W = (sum of candidate weights) / (candidates x target of the chosen light), an unbiased
// estimate of 1 / (the probability density of having chosen it).
struct RegirEntry {
    uint slot;
    float weight;
};
SHARED_ASSERT_SIZE(RegirEntry, 8);

// Own bindings of regir/mark_cells.comp and regir/build_cells.comp, after the emitter list.
SHARED_CONST uint REGIR_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;    // FrameParams (mark_cells)
SHARED_CONST uint REGIR_BINDING_GBUFFER = LIT_PASS_BINDING_FIRST + 1u;  // GBufferTexel per pixel (mark_cells)
SHARED_CONST uint REGIR_BINDING_MARKS = LIT_PASS_BINDING_FIRST + 2u;    // uint per cell: a visible surface lies in it
SHARED_CONST uint REGIR_BINDING_GRID = LIT_PASS_BINDING_FIRST + 3u;     // RegirGridInfo, then RegirEntry per cell x entry

// The cell holding world position p, or REGIR_MAX_CELLS when p lies outside the grid.
#ifdef __cplusplus
inline uint regirCellOf(const RegirGridInfo& g, glm::vec3 p) {
    glm::ivec3 c = glm::ivec3(glm::floor((p - glm::vec3(g.origin)) / g.origin.w));
    glm::ivec3 d = glm::ivec3(glm::uvec3(g.dims));
#else
uint regirCellOf(RegirGridInfo g, vec3 p) {
    ivec3 c = ivec3(floor((p - g.origin.xyz) / g.origin.w));
    ivec3 d = ivec3(g.dims.xyz);
#endif
    if (c.x < 0 || c.y < 0 || c.z < 0 || c.x >= d.x || c.y >= d.y || c.z >= d.z) return REGIR_MAX_CELLS;
    return uint(c.x + d.x * (c.y + d.y * c.z));
}

SHARED_END

#endif
