#version 460
// The lit image's histogram of log2 luminance (shared/exposure.h's bins), counted per workgroup
// in shared memory and added to the frame's histogram. Integer counts: the same image gives the
// same histogram whatever the order of the atomics.
#extension GL_GOOGLE_include_directive : require

#include "shared/exposure.h"
#include "shared/frame_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = EXPOSURE_BINDING_FRAME, std430) readonly buffer Frame { FrameParams gFrame; };
layout(set = 0, binding = EXPOSURE_BINDING_RADIANCE, std430) readonly buffer Radiance { vec4 gRadiance[]; };
layout(set = 0, binding = EXPOSURE_BINDING_HISTOGRAM, std430) buffer Histogram { uint gHistogram[]; };

shared uint sBins[EXPOSURE_BINS];

void main() {
    const uint lane = gl_LocalInvocationIndex;
    for (uint b = lane; b < EXPOSURE_BINS; b += 64u) sBins[b] = 0u;
    barrier();
    const uvec2 pixel = gl_GlobalInvocationID.xy;
    if (all(lessThan(pixel, gFrame.imageSize.xy))) {
        const vec3 c = max(gRadiance[pixel.x + pixel.y * gFrame.imageSize.x].rgb, vec3(0.0));
        const float luminance = dot(c, vec3(0.2126, 0.7152, 0.0722));
        const float t = (log2(max(luminance, 1.0e-30)) - EXPOSURE_LOG2_MIN) /
                        (EXPOSURE_LOG2_MAX - EXPOSURE_LOG2_MIN);
        const uint bin = uint(clamp(t * float(EXPOSURE_BINS), 0.0, float(EXPOSURE_BINS - 1u)));
        atomicAdd(sBins[bin], 1u);
    }
    barrier();
    for (uint b = lane; b < EXPOSURE_BINS; b += 64u)
        if (sBins[b] != 0u) atomicAdd(gHistogram[b], sBins[b]);
}
