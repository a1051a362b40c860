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

// The ReSTIR knobs as the host keeps them (lighting::LightingSettings::restir, with these
// defaults) and the shaders read them; lighting/lighting_knobs.cpp gives each its name, range
// and help. A new knob is a field here (a pad slot will do), a row there, and the shader that
// reads it. Scalars only, so std430 lays them out as C++ does; switches are uints (0 off, 1 on).
struct RestirKnobs {
    uint candidates SHARED_INIT(32u);          // M light samples per pixel
    uint spatialTaps SHARED_INIT(5u);          // neighbours merged by spatial reuse
    float spatialRadius SHARED_INIT(30.0f);    // pixels
    float temporalCap SHARED_INIT(20.0f);      // last frame's M is capped at this times M
    float depthTolerance SHARED_INIT(0.1f);    // relative depth difference a reused neighbour may have
    uint temporal SHARED_INIT(1u);             // temporal reuse
    uint spatial SHARED_INIT(1u);              // spatial reuse
    uint unbiased SHARED_INIT(0u);             // visibility-aware 1/Z normalisation (Bitterli Alg. 6)
    uint candidateVisibility SHARED_INIT(1u);  // shadow-test the chosen candidate
    uint lightTiles SHARED_INIT(0u);           // lights by power from presampled light tiles (also the cache's bounce)
    uint pad1 SHARED_INIT(0u);
    uint pad2 SHARED_INIT(0u);
    SHARED_EQUALITY(RestirKnobs)
};
SHARED_ASSERT_SIZE(RestirKnobs, 48);

// What the ReSTIR passes read: the knobs as they apply to this method (RIS turns reuse off) and
// the frame's randomness.
struct RestirParams {
    RestirKnobs knobs;
    uint area;       // area lights (else point lights at emitter centres)
    uint byPower;    // candidates by emitter power, alias table (else uniform)
    uint frameIndex;
    uint seed;
};
SHARED_ASSERT_SIZE(RestirParams, 64);

// Own bindings of the ReSTIR passes, after the emitter list. All four start with the frame, the
// parameters and the G-buffer. A buffer a pass only reads (the G-buffers; the reservoirs but its
// output and shade's final ones) is a uvec4 texel binding (loadGBuffer, loadReservoir).
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
