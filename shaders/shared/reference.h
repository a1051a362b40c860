// The reference path tracer's parameters, flags and bindings (shaders/reference/path_trace.comp).
// Packed on the host by engine/render/reference/reference_params.h. The defaults (no flag) are
// the reference as documented: box-filtered pixels, MIS of light and cosine sampling at every
// vertex that continues.
#ifndef SHARED_REFERENCE_H
#define SHARED_REFERENCE_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

// ReferenceParams.flags
// The emitter list was built with brick lights (a homogeneous emissive cell is one 8^3 light):
// the GPU needs it to tell which emitter a voxel hit by a bounce ray belongs to.
SHARED_CONST uint REFERENCE_BRICK_LIGHTS = 1u;
// One camera ray through each pixel centre instead of the box filter: for comparisons with the
// methods that shade the G-buffer's pixel centres, where edge coverage would count as their error.
SHARED_CONST uint REFERENCE_PIXEL_CENTRE = 16u;
// The older estimator: light sampling only (emission hit by bounce rays is not counted), kept
// only so the tests can show what MIS changed.
SHARED_CONST uint REFERENCE_LIGHT_SAMPLING_ONLY = 2u;
// Test probes: instead of radiance, write the emitter the GPU derives for the voxel seen through
// each pixel centre. SHAPE: (minCorner.xyz, faceMask | size << 6), -1 where none;
// POWER: (power, power / total power, 0, 0).
SHARED_CONST uint REFERENCE_PROBE_EMITTER_SHAPE = 4u;
SHARED_CONST uint REFERENCE_PROBE_EMITTER_POWER = 8u;

// Scalars only, so std430 lays them out as C++ does. The frame index is the pixel's sample count
// (the accumulation's w), so it is not here.
struct ReferenceParams {
    uint samples;  // samples per pixel in this dispatch
    uint bounces;  // indirect bounces (0: direct light only)
    uint flags;    // REFERENCE_*
    uint seed;
};
SHARED_ASSERT_SIZE(ReferenceParams, 16);

SHARED_CONST uint REFERENCE_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;         // FrameParams
SHARED_CONST uint REFERENCE_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;        // ReferenceParams
SHARED_CONST uint REFERENCE_BINDING_ACCUMULATION = LIT_PASS_BINDING_FIRST + 2u;  // vec4 per pixel: sum, samples
SHARED_CONST uint REFERENCE_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 3u;      // vec4 per pixel

SHARED_END

#endif
