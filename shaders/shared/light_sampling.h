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
    // Many shadow rays per pixel run as several dispatches (lavapipe's loop budget,
    // engine/render/loop_budget.h), each adding its range [first, end) of the alive emitters
    // (brute force) or of the samples to the pixel's running sum in the partial buffer; the
    // dispatch with end == LIGHT_SAMPLING_REST takes the rest and writes the radiance.
    uint first;
    uint end;
};
SHARED_ASSERT_SIZE(LightSamplingParams, 32);

SHARED_CONST uint LIGHT_SAMPLING_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;  // FrameParams
SHARED_CONST uint LIGHT_SAMPLING_BINDING_PARAMS =
    LIT_PASS_BINDING_FIRST + 1u;  // LightSamplingParams
SHARED_CONST uint LIGHT_SAMPLING_BINDING_GBUFFER =
    LIT_PASS_BINDING_FIRST + 2u;  // GBufferTexel per pixel
SHARED_CONST uint LIGHT_SAMPLING_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 3u;  // vec4 per pixel
// uvec4 per pixel between the dispatches of one brute-force frame: the sum so far (float bits)
// and the random state
SHARED_CONST uint LIGHT_SAMPLING_BINDING_PARTIAL = LIT_PASS_BINDING_FIRST + 4u;

SHARED_CONST uint LIGHT_SAMPLING_REST = 0xffffffffu;

SHARED_END

#endif
