#version 460
// Voxel cone tracing's gather: per pixel, six diffuse cones from the G-buffer's surface through
// this frame's radiance clipmap (vct/cone_trace.glsl), times the albedo: the indirect light the
// direct methods leave out. Writes the term alone and adds it to the frame's radiance, as the
// irradiance cache's gather and the path-traced term do.
#extension GL_GOOGLE_include_directive : require

#include "common/surface.glsl"
#include "shared/vct.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = VCT_CONES_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = VCT_CONES_BINDING_PARAMS, std430) readonly buffer VctParamsBuffer { VctParams gVct; };
layout(set = 0, binding = VCT_CONES_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = VCT_CONES_BINDING_VOLUME, std430) readonly buffer Volume { vec4 gVolume[]; };
layout(set = 0, binding = VCT_CONES_BINDING_INDIRECT, std430) writeonly buffer Indirect { vec4 gIndirect[]; };
layout(set = 0, binding = VCT_CONES_BINDING_RADIANCE, std430) buffer Radiance { vec4 gRadiance[]; };

#define VCT_VOLUME gVolume
#define VCT_ORIGIN(l) gVct.levelOrigin[l]
#include "vct/cone_trace.glsl"

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    Surface s = surfaceFrom(gGBuffer[index]);
    vec3 indirect = vec3(0.0);
    if (s.valid) {
        // The blog's self-occlusion fix: start the cones off the surface (leak mitigation), else
        // right at it.
        float offset = (gVct.flags & VCT_LEAK_MITIGATION) != 0u ? float(VCT_BASE_TEXEL) * gVct.startOffset : kRayOffset;
        indirect = s.albedo * vctGather(s.position, s.normal, offset, gFrame);
    }
    gIndirect[index] = vec4(indirect, 1.0);
    gRadiance[index] += vec4(indirect, 0.0);
}
