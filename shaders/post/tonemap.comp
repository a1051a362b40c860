#version 460
// The shown image, tonemapped (common/tonemap.glsl), where no resolve tonemaps it as it writes.
#extension GL_GOOGLE_include_directive : require

#include "common/tonemap.glsl"
#include "shared/bindings.h"
#include "shared/exposure.h"
#include "shared/frame_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = TONEMAP_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = TONEMAP_BINDING_RADIANCE, std430) readonly buffer Radiance { vec4 gRadiance[]; };
layout(set = 0, binding = TONEMAP_BINDING_LDR, std430) writeonly buffer Ldr { uint gLdr[]; };
layout(set = 0, binding = TONEMAP_BINDING_EXPOSURE, std430) readonly buffer Exposure { ExposureState gExposure; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    // The displayed image's size: the render size, or the resolve's (render/upsampling/).
    if (any(greaterThanEqual(pixel, gFrame.displaySize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.displaySize.x;
    gLdr[index] = tonemapToRgba8(gRadiance[index].rgb, shownExposure(gFrame.exposure, gExposure.value.x));
}
