#version 460
// Simple preview shading: albedo x (sky ambient + sun x N.L x shadow ray) + emission.
// Stands in for the lighting passes until ReSTIR and the irradiance cache exist.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_trace.glsl"
#include "common/camera.glsl"
#include "shared/gbuffer.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = SUN_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = SUN_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = SUN_BINDING_RADIANCE, std430) writeonly buffer Radiance { vec4 gRadiance[]; };
// Per pixel: x primary DDA steps, y shadow-ray steps, z rays traced (1 or 2).
layout(set = 0, binding = SUN_BINDING_RAY_STATS, std430) writeonly buffer RayStats { uvec4 gRayStats[]; };

const float kShadowOffset = 1.0e-3;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = gGBuffer[index];
    vec3 dir = cameraRayDirection(gFrame, pixel);
    uint face = uint(g.voxel.w);

    if (face == FACE_NONE) {
        // Sky: brighter towards the zenith.
        float up = clamp(dir.y * 0.5 + 0.5, 0.0, 1.0);
        gRadiance[index] = vec4(gFrame.skyRadiance.rgb * mix(0.6, 1.4, up), 1.0);
        gRayStats[index] = uvec4(g.data.z, 0u, 1u, 0u);
        return;
    }

    uint material = g.data.x;
    vec3 n = face == FACE_INSIDE ? -dir : vec3(faceNormal(face));
    float t = uintBitsToFloat(g.data.y);
    vec3 position = gFrame.cameraPosition.xyz + dir * t + n * kShadowOffset;
    vec3 toSun = gFrame.sunDirection.xyz;
    float nDotL = max(dot(n, toSun), 0.0);
    uint shadowSteps = 0u;
    float visible = 0.0;
    if (nDotL > 0.0 && any(greaterThan(gFrame.sunRadiance.rgb, vec3(0.0)))) {
        SceneHit shadow = traceScene(position, toSun, 1.0e30);
        shadowSteps = shadow.steps;
        visible = shadow.hit ? 0.0 : 1.0;
    }
    // A cheap sky-visibility term: faces pointing down see less sky.
    float skyFacing = 0.55 + 0.45 * n.y;
    vec3 radiance = materialAlbedo(material) * (gFrame.skyRadiance.rgb * skyFacing + gFrame.sunRadiance.rgb * nDotL * visible) +
                    materialEmission(material);
    gRadiance[index] = vec4(radiance, 1.0);
    gRayStats[index] = uvec4(g.data.z, shadowSteps, nDotL > 0.0 ? 2u : 1u, 0u);
}
