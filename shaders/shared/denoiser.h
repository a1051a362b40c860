// The denoiser's parameters and bindings (shaders/denoiser/). Packed on the host by
// engine/render/denoiser/denoiser.cpp.
#ifndef SHARED_DENOISER_H
#define SHARED_DENOISER_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

// DenoiserParams.flags
SHARED_CONST uint DENOISER_RESTART = 1u;  // drop the history: the lighting changed, or a new size
SHARED_CONST uint DENOISER_LAST = 2u;     // the last a-trous pass: it remodulates into the radiance

// Albedo below this divides the light out no further (black voxels keep a finite signal).
SHARED_CONST float DENOISER_MIN_ALBEDO = 0.02f;

struct DenoiserParams {
    uint flags;       // DENOISER_*
    uint maxHistory;  // frames the temporal mean holds at most
    uint step;        // a-trous: this pass's tap spacing in pixels
    uint pad0;
};
SHARED_ASSERT_SIZE(DenoiserParams, 16);

// denoiser/temporal.comp
SHARED_CONST uint DENOISER_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;    // FrameParams
SHARED_CONST uint DENOISER_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;   // DenoiserParams
SHARED_CONST uint DENOISER_BINDING_GBUFFER = LIT_PASS_BINDING_FIRST + 2u;  // this frame's G-buffer
// uint per pixel: last frame's surface keys (primary rays', uint texels)
SHARED_CONST uint DENOISER_BINDING_PREV_SURFACE_KEYS = LIT_PASS_BINDING_FIRST + 3u;
SHARED_CONST uint DENOISER_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 4u;  // vec4 per pixel
SHARED_CONST uint DENOISER_BINDING_PREV_HISTORY =
    LIT_PASS_BINDING_FIRST + 5u;  // vec4: demodulated mean, frames
SHARED_CONST uint DENOISER_BINDING_HISTORY = LIT_PASS_BINDING_FIRST + 6u;  // the same, written
SHARED_CONST uint DENOISER_BINDING_PREV_MOMENTS =
    LIT_PASS_BINDING_FIRST + 7u;  // vec2: luminance, its square
SHARED_CONST uint DENOISER_BINDING_MOMENTS = LIT_PASS_BINDING_FIRST + 8u;  // the same, written
SHARED_CONST uint DENOISER_BINDING_FILTERED =
    LIT_PASS_BINDING_FIRST + 9u;  // vec4: signal, its variance, written
// denoiser/atrous.comp
SHARED_CONST uint DENOISER_ATROUS_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 0u;   // FrameParams
SHARED_CONST uint DENOISER_ATROUS_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 1u;  // DenoiserParams
SHARED_CONST uint DENOISER_ATROUS_BINDING_GBUFFER =
    LIT_PASS_BINDING_FIRST + 2u;  // this frame's G-buffer (the last pass's remodulation)
SHARED_CONST uint DENOISER_ATROUS_BINDING_RADIANCE =
    LIT_PASS_BINDING_FIRST + 3u;  // vec4 per pixel: the last pass writes it
SHARED_CONST uint DENOISER_ATROUS_BINDING_INPUT =
    LIT_PASS_BINDING_FIRST + 4u;  // vec4: signal, variance
SHARED_CONST uint DENOISER_ATROUS_BINDING_OUTPUT =
    LIT_PASS_BINDING_FIRST + 5u;  // the same, written
// uint per pixel: this frame's surface keys (primary rays', uint texels)
SHARED_CONST uint DENOISER_ATROUS_BINDING_SURFACE_KEYS = LIT_PASS_BINDING_FIRST + 6u;

SHARED_END

#endif
