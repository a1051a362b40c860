// Voxel ReSTIR state (thesis §4, Bitterli et al. 2020): one reservoir per pixel, the passes'
// parameters and their own descriptor bindings. The light sample a reservoir holds is an emitter
// slot with its generation (so a removed or replaced light is recognised) and, in area mode, a
// point on one of its faces. Packed on the host by engine/render/restir/restir_params.h.
#ifndef SHARED_RESTIR_H
#define SHARED_RESTIR_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint RESERVOIR_EMPTY = 0xFFFFFFFFu;
SHARED_CONST uint LIGHT_FACE_CENTRE = 6u;  // point mode: the emitter's centre

struct Reservoir {
    uvec4 light;    // x: emitter slot (RESERVOIR_EMPTY: none), y: generation, z: face, w: packUnorm2x16(uv)
    vec4 weights;   // x: W (contribution weight), y: M (confidence), z: target pdf at its pixel,
                    // w: visibility of the sample at its pixel (0: the candidate pass found it
                    // occluded; 1: visible, untested or already applied to W)
};
SHARED_ASSERT_SIZE(Reservoir, 32);

// Scalars only, so std430 lays them out as C++ does. Switches are uints (0 off, 1 on).
struct RestirParams {
    uint candidates;           // M light samples per pixel
    uint spatialTaps;          // neighbours merged by spatial reuse
    uint frameIndex;
    uint seed;
    float spatialRadius;       // pixels
    float temporalCap;         // temporal M cap, times the current M
    float depthTolerance;      // relative depth difference a reused neighbour may have
    uint area;                 // area lights (else point lights at emitter centres)
    uint byPower;              // candidates by emitter power, alias table (else uniform)
    uint unbiased;             // visibility-aware 1/Z normalisation (Bitterli Alg. 6)
    uint temporal;             // temporal reuse
    uint spatial;              // spatial reuse
    uint candidateVisibility;  // shadow-test the chosen candidate
    uint pad0, pad1, pad2;
};
SHARED_ASSERT_SIZE(RestirParams, 64);

// Own bindings of the ReSTIR passes, after the emitter list. All four start with the frame, the
// parameters and the G-buffer.
SHARED_CONST uint RESTIR_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;    // FrameParams
SHARED_CONST uint RESTIR_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;   // RestirParams
SHARED_CONST uint RESTIR_BINDING_GBUFFER = LIT_PASS_BINDING_FIRST + 2u;  // GBufferTexel per pixel
// restir/initial_candidates.comp
SHARED_CONST uint RESTIR_INITIAL_BINDING_OUT = LIT_PASS_BINDING_FIRST + 3u;  // candidate reservoirs
// restir/temporal_reuse.comp
SHARED_CONST uint RESTIR_TEMPORAL_BINDING_PREV_GBUFFER = LIT_PASS_BINDING_FIRST + 3u;
SHARED_CONST uint RESTIR_TEMPORAL_BINDING_CANDIDATES = LIT_PASS_BINDING_FIRST + 4u;
SHARED_CONST uint RESTIR_TEMPORAL_BINDING_PREVIOUS = LIT_PASS_BINDING_FIRST + 5u;  // last frame's final reservoirs
SHARED_CONST uint RESTIR_TEMPORAL_BINDING_OWN = LIT_PASS_BINDING_FIRST + 6u;
// restir/spatial_reuse.comp
SHARED_CONST uint RESTIR_SPATIAL_BINDING_OWN = LIT_PASS_BINDING_FIRST + 3u;
SHARED_CONST uint RESTIR_SPATIAL_BINDING_CANDIDATES = LIT_PASS_BINDING_FIRST + 4u;
SHARED_CONST uint RESTIR_SPATIAL_BINDING_OUT = LIT_PASS_BINDING_FIRST + 5u;
// restir/shade.comp
SHARED_CONST uint RESTIR_SHADE_BINDING_FINAL = LIT_PASS_BINDING_FIRST + 3u;
SHARED_CONST uint RESTIR_SHADE_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 4u;

SHARED_END

#endif
