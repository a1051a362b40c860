// Per-frame constants for the render passes: camera, sky, image size, frame index and seed.
#ifndef SHARED_FRAME_PARAMS_H
#define SHARED_FRAME_PARAMS_H
#include "interop.h"

SHARED_BEGIN

struct FrameParams {
    vec4 cameraPosition;  // xyz world position (voxel units), w = tan(fovY / 2)
    vec4 cameraForward;   // xyz unit, w = aspect (width / height)
    vec4 cameraRight;     // xyz unit
    vec4 cameraUp;        // xyz unit
    vec4 sunDirection;    // xyz unit vector towards the sun
    vec4 sunRadiance;     // rgb
    vec4 skyRadiance;     // rgb, ambient and background
    uvec4 imageSize;      // x width, y height, zw unused (randomness is seeded from RestirParams)
    vec4 exposure;        // x fixed exposure multiplier, y 1: auto exposure's instead
    // The previous frame's camera, for motion vectors (equal to the current one on frame 0).
    vec4 prevCameraPosition;
    vec4 prevCameraForward;
    vec4 prevCameraRight;
    vec4 prevCameraUp;
    // This frame's presampled light tiles (shared/light_tiles.h): xy the buffer's device address
    // (low, high word), 0 when the frame drew none; zw unused.
    uvec4 lightTiles;
    // This frame's ReGIR grid (shared/regir.h): xy its buffer's device address, 0 when the frame
    // filled none; zw unused.
    uvec4 regirGrid;
    // The reconstruction's (render/upsampling/): xy this frame's sub-pixel offset of the primary
    // rays in pixels, in (-0.5, 0.5); zw the previous frame's. 0 without it.
    vec4 jitter;
    // xy the size of the displayed image (the resolve's output; imageSize without it), zw unused.
    uvec4 displaySize;
};
SHARED_ASSERT_SIZE(FrameParams, 272);

SHARED_END

#endif
