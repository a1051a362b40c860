// Voxel ReSTIR state (thesis §4, Bitterli et al. 2020): one reservoir per pixel and the pass
// parameters. The light sample a reservoir holds is an emitter slot with its generation (so a
// removed or replaced light is recognised) and, in area mode, a point on one of its faces.
#ifndef SHARED_RESTIR_H
#define SHARED_RESTIR_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint RESERVOIR_EMPTY = 0xFFFFFFFFu;
SHARED_CONST uint LIGHT_FACE_CENTRE = 6u;  // point mode: the emitter's centre

// RestirParams.config.y flags
SHARED_CONST uint RESTIR_AREA = 1u;          // area lights (else point lights at emitter centres)
SHARED_CONST uint RESTIR_ALIAS = 2u;         // candidates by emitter power (else uniform)
SHARED_CONST uint RESTIR_UNBIASED = 4u;      // visibility-aware 1/Z normalisation (Bitterli Alg. 6)
SHARED_CONST uint RESTIR_TEMPORAL = 8u;      // temporal reuse
SHARED_CONST uint RESTIR_SPATIAL = 16u;      // spatial reuse
SHARED_CONST uint RESTIR_CANDIDATE_VISIBILITY = 32u;  // shadow-test the chosen candidate

struct Reservoir {
    uvec4 light;    // x: emitter slot (RESERVOIR_EMPTY: none), y: generation, z: face, w: packUnorm2x16(uv)
    vec4 weights;   // x: W (contribution weight), y: M (confidence), z: target pdf at its pixel,
                    // w: visibility of the sample at its pixel (0: the candidate pass found it
                    // occluded; 1: visible, untested or already applied to W)
};
SHARED_ASSERT_SIZE(Reservoir, 32);

struct RestirParams {
    uvec4 config;   // x: candidates M, y: RESTIR_* flags, z: spatial taps, w: frame index
    vec4 reuse;     // x: spatial radius (pixels), y: temporal M cap (x current M), z: depth tolerance, w: unused
    uvec4 seeds;    // x: seed, y: shadow rays per pixel (light-sampling baseline), zw: unused
};
SHARED_ASSERT_SIZE(RestirParams, 48);

SHARED_END

#endif
