// Sky light from discrete visibility fields (Günay & Akyüz, "Real-time Discrete Visibility
// Fields for Ray-Traced Dynamic Scenes"): the layouts, constants and bindings of
// shaders/dvf_sky/ and engine/render/dvf_sky/. A mask is kept per (8³ cell, face orientation):
// 64 bits over a hemi-octahedral 8x8 grid of directions about the face normal, bit set where
// rays from the cell's anchor face escape the world to the sky.
#ifndef SHARED_DVF_SKY_H
#define SHARED_DVF_SKY_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint DVF_GRID = 8u;                  // hemi-octahedral grid side: 8x8 directions
SHARED_CONST uint DVF_DIRECTIONS = 64u;           // one uint64 (two uints) per mask
SHARED_CONST uint DVF_CELL_SHIFT = 3u;            // cells of 8³ voxels: the brick grid's cells
SHARED_CONST uint DVF_CAPACITY = 65536u;          // slots in the hash table (a power of two)
SHARED_CONST uint DVF_MAX_PROBES = 32u;           // linear probing gives up after this many slots
SHARED_CONST uint DVF_RAYS_PER_DIRECTION = 4u;    // rays per direction texel (2x2 strata); the bit is their weighted answer, dithered
SHARED_CONST uint DVF_MAX_EDITS = 64u;            // edit spheres per frame (more are merged into one)
SHARED_CONST uint DVF_EMPTY_KEY = 0u;            // a free slot: keys are the packed (cell, face) + 1

// DvfSlot.state bits
SHARED_CONST uint DVF_STATE_VALID = 1u;   // the mask has been traced at least once
SHARED_CONST uint DVF_STATE_QUEUED = 2u;  // in the trace queue; not enqueued again until traced

// DvfParams.flags
SHARED_CONST uint DVF_FLAG_RESTART = 1u;  // sky reference: drop the running sum

// Key of a (cell, face): 1 + (x 10 bits, y 9 bits, z 10 bits, face 3 bits), so that a zeroed
// table is empty. Worlds up to 8192 x 4096 x
// 8192 voxels; the renderer turns the sky term off beyond that.
SHARED_CONST uint DVF_MAX_CELLS_XZ = 1024u;
SHARED_CONST uint DVF_MAX_CELLS_Y = 512u;

struct DvfSlot {
    uint key;       // DVF_EMPTY_KEY when free
    uint state;     // DVF_STATE_*
    uint anchorRank;  // the anchor within the cell, as dvfAnchorRank packs it: the largest rank (a
                      // hash-chosen one) of the pixels that asked before the mask was first traced
    uint pad1;
    ivec4 anchor;   // xyz the cell's lowest voxel; the anchor, the open-side voxel of a face that asked
                    // for the slot (rays start on that face), is dvfAnchor(): chosen by a maximum, not
                    // by which pixel came first, so the masks do not depend on thread timing
    uvec4 maskDirty;  // xy the visibility mask (low, high 32 directions), zw the directions to re-trace
};
SHARED_ASSERT_SIZE(DvfSlot, 48);

// Written by the GPU passes only; copied to the host after each frame for the statistics.
struct DvfHeader {
    uint used;        // slots taken
    uint head;        // queue: next entry to trace
    uint tail;        // queue: one past the last entry
    uint batchStart;  // this frame's batch: queue[batchStart .. batchStart + batchCount)
    uint batchCount;
    uint tracedRays;  // rays the build pass traced this frame
    uint pad0, pad1;
};
SHARED_ASSERT_SIZE(DvfHeader, 32);

// Per-frame parameters from the host.
struct DvfParams {
    uint budget;     // masks traced per frame at most (workgroups of the build pass)
    uint editCount;  // edit spheres in `edits`
    uint frame;      // frame index and seed: the jitter of the rays
    uint seed;
    uint flags;      // DVF_FLAG_*
    uint samples;    // sky reference: rays per pixel per frame
    uint pad0, pad1;
    vec4 edits[DVF_MAX_EDITS];  // xyz centre, w radius (voxels): regions whose voxels changed
};
SHARED_ASSERT_SIZE(DvfParams, 32 + 16 * 64);

SHARED_CONST uint DVF_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;     // FrameParams
SHARED_CONST uint DVF_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;    // DvfParams
SHARED_CONST uint DVF_BINDING_HEADER = LIT_PASS_BINDING_FIRST + 2u;    // DvfHeader
SHARED_CONST uint DVF_BINDING_SLOTS = LIT_PASS_BINDING_FIRST + 3u;     // DvfSlot[DVF_CAPACITY]
SHARED_CONST uint DVF_BINDING_QUEUE = LIT_PASS_BINDING_FIRST + 4u;     // uint slot index[DVF_CAPACITY], a ring
SHARED_CONST uint DVF_BINDING_WEIGHTS = LIT_PASS_BINDING_FIRST + 5u;   // float[6 * 64]: per face and direction
SHARED_CONST uint DVF_BINDING_GBUFFER = LIT_PASS_BINDING_FIRST + 6u;   // GBufferTexel per pixel
SHARED_CONST uint DVF_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 7u;  // vec4 per pixel, the term added
SHARED_CONST uint DVF_BINDING_SKY = LIT_PASS_BINDING_FIRST + 8u;       // vec4 per pixel: the sky term alone (sky reference: sum, rays)

SHARED_END

#endif
