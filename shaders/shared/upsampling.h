// Temporal upsampling's parameters and bindings (shaders/upsampling/resolve.comp). Packed on the
// host by engine/render/upsampling/temporal_upsampling.cpp.
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

SHARED_CONST uint UPSAMPLING_BINDING_FRAME = 0u;     // FrameParams
SHARED_CONST uint UPSAMPLING_BINDING_PARAMS = 1u;    // UpsamplingParams
SHARED_CONST uint UPSAMPLING_BINDING_GBUFFER = 2u;   // this frame's G-buffer (render size): motion
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

SHARED_END

#endif
