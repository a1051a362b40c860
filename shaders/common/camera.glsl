// Pinhole camera rays from FrameParams; mirrors engine/render/camera.h.
#ifndef COMMON_CAMERA_GLSL
#define COMMON_CAMERA_GLSL

#include "shared/frame_params.h"

// Unit direction through `imagePosition`, in pixel units (pixel i spans [i, i + 1); y grows
// downwards in the image).
vec3 cameraRayDirectionAt(FrameParams f, vec2 imagePosition) {
    vec2 ndc = imagePosition / vec2(f.imageSize.xy) * 2.0 - 1.0;
    float tanHalf = f.cameraPosition.w;
    vec3 d = f.cameraForward.xyz + f.cameraRight.xyz * (ndc.x * tanHalf * f.cameraForward.w) -
             f.cameraUp.xyz * (ndc.y * tanHalf);
    return normalize(d);
}

// Unit direction through `pixel`'s sample: its centre, moved by the frame's jitter.
vec3 cameraRayDirection(FrameParams f, uvec2 pixel) { return cameraRayDirectionAt(f, vec2(pixel) + 0.5 + f.jitter.xy); }

#endif
