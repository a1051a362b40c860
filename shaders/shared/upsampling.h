// Temporal upsampling's parameters and bindings (shaders/upsampling/: the pre-pass per render
// pixel, summarize_neighbourhood.comp, and the resolve per display pixel, resolve.comp). Packed on
// the host by engine/render/upsampling/temporal_upsampling.cpp.
#ifndef SHARED_UPSAMPLING_H
#define SHARED_UPSAMPLING_H
#include "interop.h"

SHARED_BEGIN

// UpsamplingParams.flags
SHARED_CONST uint UPSAMPLING_RESTART = 1u;  // no history: the first frame, or a new display size
// The world, its lights or the sky changed: the history counts as half a frame at most.
SHARED_CONST uint UPSAMPLING_LIGHTING_CHANGED = 2u;
// A dynamic object moved or appeared: its shadows and light may have moved unannounced.
SHARED_CONST uint UPSAMPLING_OBJECTS_MOVED = 4u;
// The camera and the world have been still for a whole jitter cycle (or the history's length, if
// shorter): every display pixel has had its samples, and a still pixel takes no more.
SHARED_CONST uint UPSAMPLING_SETTLED = 8u;

struct UpsamplingParams {
    uint flags;        // UPSAMPLING_*
    float maxHistory;  // frames of samples the display history holds at most
    float clipGamma;   // history clipped to the neighbourhood's mean +- gamma standard deviations
    uint pad0;
    // The voxels this frame's edits changed, with a cell around them (min inclusive, max
    // exclusive; empty when no edit): a static surface seen there has no history.
    ivec4 editedMin;
    ivec4 editedMax;
};
SHARED_ASSERT_SIZE(UpsamplingParams, 48);

// The resolve's bindings (shaders/upsampling/resolve.comp).
SHARED_CONST uint UPSAMPLING_BINDING_FRAME = 0u;   // FrameParams
SHARED_CONST uint UPSAMPLING_BINDING_PARAMS = 1u;  // UpsamplingParams
// UPSAMPLING_NEIGHBOURHOOD_TEXELS uvec4 texels per render pixel, from the pre-pass
SHARED_CONST uint UPSAMPLING_BINDING_NEIGHBOURHOOD = 2u;
SHARED_CONST uint UPSAMPLING_BINDING_RADIANCE = 3u;  // vec4 per render pixel
SHARED_CONST uint UPSAMPLING_BINDING_PREV_DISPLAY =
    4u;                                               // vec4 per display pixel: rgb, history weight
SHARED_CONST uint UPSAMPLING_BINDING_DISPLAY = 5u;    // the same, written
SHARED_CONST uint UPSAMPLING_BINDING_PREV_KEYS = 6u;  // uint per display pixel: its surface's key
SHARED_CONST uint UPSAMPLING_BINDING_KEYS = 7u;       // the same, written
// uint per render pixel: the surface keys primary rays wrote (uint texels)
SHARED_CONST uint UPSAMPLING_BINDING_SURFACE_KEYS = 8u;
SHARED_CONST uint UPSAMPLING_BINDING_EXPOSURE = 9u;  // ExposureState (shared/exposure.h)
// uint per display pixel: the display tonemapped, packed RGBA8 (common/tonemap.glsl), written
SHARED_CONST uint UPSAMPLING_BINDING_LDR = 10u;

// The pre-pass's bindings (shaders/upsampling/summarize_neighbourhood.comp), per render pixel.
SHARED_CONST uint NEIGHBOURHOOD_BINDING_FRAME = 0u;         // FrameParams
SHARED_CONST uint NEIGHBOURHOOD_BINDING_PARAMS = 1u;        // UpsamplingParams
SHARED_CONST uint NEIGHBOURHOOD_BINDING_GBUFFER = 2u;       // G-buffer texels: motion, voxel
SHARED_CONST uint NEIGHBOURHOOD_BINDING_RADIANCE = 3u;      // vec4 texels
SHARED_CONST uint NEIGHBOURHOOD_BINDING_SURFACE_KEYS = 4u;  // uint texels
SHARED_CONST uint NEIGHBOURHOOD_BINDING_OUT = 5u;           // uvec4 per texel, written

// What the pre-pass keeps of a render pixel's 3x3 neighbourhood, in uvec4 texels (index
// UPSAMPLING_NEIGHBOURHOOD_TEXELS * pixel + t):
//   0: floatBits(motion.xy) of the pixel's own sample, NEIGHBOURHOOD_FLAG_* | key count << 8, 0
//   1: floatBits(mean YCoCg), packHalf2x16(sigma.x, sigma.y)
//   2: packHalf2x16(sigma.z, lowest.x), (lowest.y, lowest.z), (highest.x, highest.y),
//      (highest.z, 0): lowest rounded down and highest up, so the box never shrinks
//   3: up to four distinct surface keys, the pixel's own first, the rest repeating it; with a
//      count above four the resolve reads the nine keys itself
SHARED_CONST uint UPSAMPLING_NEIGHBOURHOOD_TEXELS = 4u;
SHARED_CONST uint NEIGHBOURHOOD_FLAG_MOTION = 1u;  // the sample's motion is valid
// A static surface within a cell of this frame's edits (UpsamplingParams.editedMin/Max)
SHARED_CONST uint NEIGHBOURHOOD_FLAG_EDITED = 2u;
SHARED_CONST uint NEIGHBOURHOOD_KEY_COUNT_SHIFT = 8u;

SHARED_END

#endif
