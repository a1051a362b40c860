#version 460
// The running mean of the frame's radiance while camera, world, lights and sky stay still: the
// history moves 1/n of the way to this frame's radiance, and the radiance becomes the mean. With
// n capped, an exponential moving average that still follows slow changes.
#extension GL_GOOGLE_include_directive : require

#include "shared/accumulation.h"
#include "shared/frame_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = ACCUMULATION_BINDING_FRAME, std430) readonly buffer Frame { FrameParams gFrame; };
layout(set = 0, binding = ACCUMULATION_BINDING_PARAMS, std430) readonly buffer Params { AccumulationParams gParams; };
layout(set = 0, binding = ACCUMULATION_BINDING_HISTORY, std430) buffer History { vec4 gHistory[]; };
layout(set = 0, binding = ACCUMULATION_BINDING_RADIANCE, std430) buffer Radiance { vec4 gRadiance[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    vec4 mean = gParams.frames <= 1u ? gRadiance[index]
                                      : mix(gHistory[index], gRadiance[index], 1.0 / float(gParams.frames));
    gHistory[index] = mean;
    gRadiance[index] = mean;
}
