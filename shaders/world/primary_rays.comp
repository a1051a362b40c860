#version 460
// Primary rays: one camera ray per pixel through the brick grid, written to the G-buffer.
#extension GL_GOOGLE_include_directive : require

#include "common/brick_traversal.glsl"
#include "common/camera.glsl"
#include "shared/gbuffer.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = PASS_BINDING_FIRST + 0, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = PASS_BINDING_FIRST + 1, std430) writeonly buffer GBuffer { GBufferTexel gGBuffer[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;

    vec3 dir = cameraRayDirection(gFrame, pixel);
    TraceResult hit = traceRay(gFrame.cameraPosition.xyz, dir, 1.0e30, true);

    GBufferTexel texel;
    texel.voxel = ivec4(hit.voxel, int(hit.hit ? hit.face : FACE_NONE));
    texel.data = uvec4(hit.material, floatBitsToUint(hit.t), hit.steps, 0u);
    gGBuffer[index] = texel;
}
