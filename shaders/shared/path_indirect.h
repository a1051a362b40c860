// The path-traced indirect term's parameters, flags and bindings (shaders/path_indirect/
// trace_paths.comp). Packed on the host by engine/render/path_indirect/path_indirect.cpp.
#ifndef SHARED_PATH_INDIRECT_H
#define SHARED_PATH_INDIRECT_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

// PathIndirectParams.flags
// The emitter list was built with brick lights (the MIS weight of an emitter hit needs its shape).
SHARED_CONST uint PATH_INDIRECT_BRICK_LIGHTS = 1u;
// Drop the accumulated sum: the camera moved, the world or the settings changed, or accumulation is
// off.
SHARED_CONST uint PATH_INDIRECT_RESTART = 2u;
// The frame's last dispatch (a frame's paths may take several, engine/render/loop_budget.h): it
// writes the indirect term and adds it to the radiance.
SHARED_CONST uint PATH_INDIRECT_FINAL = 4u;

struct PathIndirectParams {
    uint samples;  // bounce paths per pixel in this dispatch
    uint bounces;  // bounces per path (>= 1)
    uint flags;    // PATH_INDIRECT_*
    uint frame;    // the renderer's frame index: with the seed, it seeds the frame's paths
    uint seed;
    uint firstSample;  // the frame's paths before this dispatch's
    uint pad0, pad1;
};
SHARED_ASSERT_SIZE(PathIndirectParams, 32);

SHARED_CONST uint PATH_INDIRECT_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;   // FrameParams
SHARED_CONST uint PATH_INDIRECT_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;  // PathIndirectParams
SHARED_CONST uint PATH_INDIRECT_BINDING_GBUFFER =
    LIT_PASS_BINDING_FIRST + 2u;  // GBufferTexel per pixel
SHARED_CONST uint PATH_INDIRECT_BINDING_ACCUMULATION =
    LIT_PASS_BINDING_FIRST + 3u;  // vec4 per pixel: sum, paths
SHARED_CONST uint PATH_INDIRECT_BINDING_INDIRECT =
    LIT_PASS_BINDING_FIRST + 4u;  // vec4 per pixel, written
SHARED_CONST uint PATH_INDIRECT_BINDING_RADIANCE =
    LIT_PASS_BINDING_FIRST + 5u;  // vec4 per pixel, added to

SHARED_END

#endif
