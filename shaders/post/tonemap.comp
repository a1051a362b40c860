#version 460
// Linear radiance -> exposure -> ACES filmic curve (Narkowicz 2015 fit) -> sRGB, packed RGBA8.
#extension GL_GOOGLE_include_directive : require

#include "shared/bindings.h"
#include "shared/exposure.h"
#include "shared/frame_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = TONEMAP_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = TONEMAP_BINDING_RADIANCE, std430) readonly buffer Radiance { vec4 gRadiance[]; };
layout(set = 0, binding = TONEMAP_BINDING_LDR, std430) writeonly buffer Ldr { uint gLdr[]; };
layout(set = 0, binding = TONEMAP_BINDING_EXPOSURE, std430) readonly buffer Exposure { ExposureState gExposure; };

vec3 acesFilm(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    // The displayed image's size: the render size, or the resolve's (render/upsampling/).
    if (any(greaterThanEqual(pixel, gFrame.displaySize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.displaySize.x;
    // Fixed, or metered by auto exposure (shaders/exposure/) this frame.
    float exposure = gFrame.exposure.y != 0.0 ? gExposure.value.x : gFrame.exposure.x;
    vec3 c = linearToSrgb(acesFilm(max(gRadiance[index].rgb, vec3(0.0)) * exposure));
    gLdr[index] = packUnorm4x8(vec4(c, 1.0));
}
