// Flags of the reference path tracer (shaders/reference/path_trace.comp), passed in
// RestirParams.seeds.w. The defaults (no flag) are the reference as documented: box-filtered
// pixels, MIS of light and cosine sampling at every vertex that continues.
#ifndef SHARED_REFERENCE_H
#define SHARED_REFERENCE_H
#include "interop.h"

SHARED_BEGIN

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

SHARED_END

#endif
