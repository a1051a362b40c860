// The light-sampling baselines' parameters and bindings (shaders/baselines/light_sampling.comp):
// N light samples with N shadow rays per pixel (uniform or by power), or every light once
// (brute force). Packed on the host by engine/render/baselines/light_sampling_params.h.
#ifndef SHARED_LIGHT_SAMPLING_H
#define SHARED_LIGHT_SAMPLING_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

// Scalars only, so std430 lays them out as C++ does. Switches are uints (0 off, 1 on).
struct LightSamplingParams {
    uint samples;     // light samples (and shadow rays) per pixel
    uint everyLight;  // brute force: every alive emitter once instead of `samples` draws
    uint area;        // area lights (else point lights at emitter centres)
    uint byPower;     // draws by emitter power, alias table (else uniform)
    uint frameIndex;
    uint seed;
    uint pad0, pad1;
};
SHARED_ASSERT_SIZE(LightSamplingParams, 32);

SHARED_CONST uint LIGHT_SAMPLING_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;     // FrameParams
SHARED_CONST uint LIGHT_SAMPLING_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;    // LightSamplingParams
SHARED_CONST uint LIGHT_SAMPLING_BINDING_GBUFFER = LIT_PASS_BINDING_FIRST + 2u;   // GBufferTexel per pixel
SHARED_CONST uint LIGHT_SAMPLING_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 3u;  // vec4 per pixel

SHARED_END

#endif
