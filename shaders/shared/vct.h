// Voxel cone tracing (`--indirect vct`, render/vct/, shaders/vct/): the radiance clipmap's layout,
// parameters, flags and bindings. Packed on the host by engine/render/vct/voxel_cone_tracing.cpp.
//
// The clipmap: VCT_MAX_LEVELS levels of VCT_RES^3 texels centred on the camera; level l's texel
// is VCT_BASE_TEXEL << l voxels wide, so each level covers twice the extent of the one before at
// half the resolution — the coarser levels are the finer ones' mips where they overlap. Memory is
// fixed (independent of the world). A texel is stored at its world texel coordinate modulo
// VCT_RES (toroidal addressing), so when the camera moves, the texels that stay in a level keep
// their place and their values; only those entering it are injected at once. Each texel holds
// VCT_SLOTS vec4: for each of the six axis directions a cone may travel in, the radiance (rgb) of
// the surfaces facing it and the fraction of the texel's cross-section they cover along that axis
// (a): anisotropic, so a thin wall's lit side is not seen through its dark side.
#ifndef SHARED_VCT_H
#define SHARED_VCT_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint VCT_RES = 32u;  // texels per axis and level
SHARED_CONST uint VCT_MAX_LEVELS = 4u;
SHARED_CONST uint VCT_BASE_TEXEL = 2u;  // level 0's texel, in voxels
SHARED_CONST uint VCT_SLOTS =
    6u;  // slot d: cones travelling along axis d/2, + if d odd (face order)
SHARED_CONST uint VCT_TEXELS_PER_LEVEL = VCT_RES * VCT_RES * VCT_RES;

// VctParams.flags
// Leak mitigation on: directional radiance and coverage, and cones start off the surface along
// its normal. Off: isotropic texels (the mean radiance, opacity = the solid volume fraction) and
// cones start at the surface — the textbook volume, for measuring what the mitigation buys.
SHARED_CONST uint VCT_LEAK_MITIGATION = 1u;
// Inject a second bounce: each injected surface also reflects what the last frame's volume
// gives it (cone-traced from that volume).
SHARED_CONST uint VCT_EXTRA_BOUNCE = 2u;
// The last frame's volume is valid (same levels, settings, world and lights): texels that stay in
// the clipmap keep their values unless refreshed, and the extra bounce reads it.
SHARED_CONST uint VCT_PREVIOUS_VALID = 4u;
// The volume is updated in place (no extra bounce, so nothing reads last frame's values while
// this frame's are written): texels that keep their values are left as they are, not copied.
SHARED_CONST uint VCT_IN_PLACE = 8u;

struct VctParams {
    ivec4
        levelOrigin[4];   // per level: xyz its minimum corner in voxels, w its texel size in voxels
    ivec4 prevOrigin[4];  // the same for the last frame's volume (the extra bounce reads it)
    // Texels that meet this box (voxels, max exclusive) are injected every frame: the dynamic
    // objects' grid now and last frame. Empty when min >= max.
    ivec4 dynamicMin;
    ivec4 dynamicMax;
    uint levels;  // levels in use (1..VCT_MAX_LEVELS)
    uint flags;   // VCT_*
    uint seed;
    float startOffset;   // cone start along the normal, in level-0 texels (with leak mitigation)
    uint refreshPeriod;  // other texels are re-injected every this many frames, in turn
    uint frame;          // the renderer's frame index (picks this frame's share)
    uint pad0, pad1;
};
SHARED_ASSERT_SIZE(VctParams, 192);

// The injection's texel list (VCT_INJECT_BINDING_LIST): VCT_LIST_HEADER words — the count of
// listed texels, then the indirect dispatch's three workgroup counts — then one texel index per
// listed texel (x + VCT_RES * (y + VCT_RES * (z + VCT_RES * level))).
SHARED_CONST uint VCT_LIST_COUNT = 0u;
SHARED_CONST uint VCT_LIST_ARGS = 1u;
SHARED_CONST uint VCT_LIST_HEADER = 4u;
SHARED_CONST uint VCT_INJECT_GROUP_SIZE = 64u;  // inject_radiance.comp's workgroup

// vct.classify visits blocks of VCT_BLOCK^3 texels, one workgroup each, from a list the host
// makes (render/vct/vct_block_list.h; VCT_INJECT_BINDING_BLOCKS): a block's index is
// x + VCT_BLOCKS_PER_AXIS * (y + VCT_BLOCKS_PER_AXIS * (z + VCT_BLOCKS_PER_AXIS * level)).
SHARED_CONST uint VCT_BLOCK = 4u;
SHARED_CONST uint VCT_BLOCKS_PER_AXIS = VCT_RES / VCT_BLOCK;
SHARED_CONST uint VCT_BLOCKS_PER_LEVEL =
    VCT_BLOCKS_PER_AXIS * VCT_BLOCKS_PER_AXIS * VCT_BLOCKS_PER_AXIS;

// classify_texels.comp, list_dispatch.comp and inject_radiance.comp: world + lights, then
SHARED_CONST uint VCT_INJECT_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;   // FrameParams
SHARED_CONST uint VCT_INJECT_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;  // VctParams
SHARED_CONST uint VCT_INJECT_BINDING_PREVIOUS =
    LIT_PASS_BINDING_FIRST + 2u;  // vec4 volume, last frame's
SHARED_CONST uint VCT_INJECT_BINDING_VOLUME = LIT_PASS_BINDING_FIRST + 3u;  // vec4 volume, written
SHARED_CONST uint VCT_INJECT_BINDING_LIST = LIT_PASS_BINDING_FIRST + 4u;    // uint: the texel list
SHARED_CONST uint VCT_INJECT_BINDING_BLOCKS =
    LIT_PASS_BINDING_FIRST + 5u;  // uint: the blocks vct.classify visits
// trace_cones.comp: world + lights, then
SHARED_CONST uint VCT_CONES_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;   // FrameParams
SHARED_CONST uint VCT_CONES_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;  // VctParams
SHARED_CONST uint VCT_CONES_BINDING_GBUFFER =
    LIT_PASS_BINDING_FIRST + 2u;                                           // GBufferTexel per pixel
SHARED_CONST uint VCT_CONES_BINDING_VOLUME = LIT_PASS_BINDING_FIRST + 3u;  // vec4 volume
SHARED_CONST uint VCT_CONES_BINDING_INDIRECT =
    LIT_PASS_BINDING_FIRST + 4u;  // vec4 per pixel, written
SHARED_CONST uint VCT_CONES_BINDING_RADIANCE =
    LIT_PASS_BINDING_FIRST + 5u;  // vec4 per pixel, added to

SHARED_END

#endif
