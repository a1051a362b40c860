#version 460
// Primary rays: one camera ray per pixel through the static world and the dynamic grid, written
// to the G-buffer with the set the voxel belongs to and a motion vector that follows moving
// objects, and the pixel's surface key to a buffer of its own: the resolve and the denoiser
// compare keys at every filter tap and history texel, and one uint per tap is a quarter of the
// G-buffer texels (and none of the arithmetic) that computing it there would cost.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_trace.glsl"
#include "common/camera.glsl"
#include "common/surface_key.glsl"
#include "shared/gbuffer.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = PRIMARY_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = PRIMARY_BINDING_GBUFFER, std430) writeonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = PRIMARY_BINDING_SURFACE_KEYS, std430) writeonly buffer SurfaceKeys { uint gSurfaceKeys[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;

    vec3 dir = cameraRayDirection(gFrame, pixel);
    SceneHit hit = traceScene(gFrame.cameraPosition.xyz, dir, 1.0e30);

    GBufferTexel texel;
    texel.voxel = ivec4(hit.voxel, int(hit.hit ? hit.face : FACE_NONE));
    texel.data = uvec4(hit.material, floatBitsToUint(hit.t), hit.steps, hit.dynamicSet ? GBUFFER_FLAG_DYNAMIC : 0u);
    vec3 position = gFrame.cameraPosition.xyz + dir * hit.t;
    texel.position = vec4(position, 0.0);
    texel.motion = vec4(0.0);
    if (hit.hit) {
        // Where the previous frame's camera saw this point: the same point in the static world;
        // on an object, the point that moved here (its previous pose times the inverse of this one).
        vec3 prevPosition = position;
        if (hit.dynamicSet) {
            int object = dynamicObjectAt(hit.voxel);
            if (object >= 0) prevPosition = (dynamicObjectPrevFromCurrent(uint(object)) * vec4(position, 1.0)).xyz;
        }
        vec3 rel = prevPosition - gFrame.prevCameraPosition.xyz;
        float z = dot(rel, gFrame.prevCameraForward.xyz);
        if (z > 1e-4) {
            // The previous camera's own field of view and aspect: a path may zoom.
            float tanHalf = gFrame.prevCameraPosition.w;
            vec2 ndc = vec2(dot(rel, gFrame.prevCameraRight.xyz) / (z * tanHalf * gFrame.prevCameraForward.w),
                            -dot(rel, gFrame.prevCameraUp.xyz) / (z * tanHalf));
            vec2 prevPixel = (ndc * 0.5 + 0.5) * vec2(gFrame.imageSize.xy);
            texel.motion = vec4(prevPixel, length(rel), 1.0);
        }
    }
    gGBuffer[index] = texel;
    gSurfaceKeys[index] = surfaceKey(texel);
}
