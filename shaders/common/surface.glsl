// Reading the G-buffer back as a shading surface.
#ifndef COMMON_SURFACE_GLSL
#define COMMON_SURFACE_GLSL

#include "common/emitters.glsl"
#include "shared/frame_params.h"
#include "common/gbuffer_load.glsl"
#include "shared/gbuffer.h"

Surface surfaceFrom(GBufferTexel g) {
    Surface s;
    s.face = uint(g.voxel.w);
    s.valid = s.face < 6u;
    s.position = g.position.xyz;
    s.normal = s.valid ? faceNormalF(s.face) : vec3(0.0);
    s.albedo = materialAlbedo(g.data.x);
    s.emission = s.face == FACE_NONE ? vec3(0.0) : materialEmission(g.data.x);
    return s;
}

float gbufferDistance(GBufferTexel g) { return uintBitsToFloat(g.data.y); }

// Sun light (a directional light of irradiance sunRadiance) with one shadow ray.
vec3 sunUnshadowed(Surface s, FrameParams f) {
    float cosine = dot(s.normal, f.sunDirection.xyz);
    if (cosine <= 0.0 || !any(greaterThan(f.sunRadiance.rgb, vec3(0.0)))) return vec3(0.0);
    return s.albedo / PI * f.sunRadiance.rgb * cosine;
}

vec3 sunLight(Surface s, FrameParams f) {
    vec3 light = sunUnshadowed(s, f);
    if (!any(greaterThan(light, vec3(0.0)))) return vec3(0.0);
    SceneHit hit = traceScene(s.position + s.normal * kRayOffset, f.sunDirection.xyz, 1.0e30);
    return hit.hit ? vec3(0.0) : light;
}

vec3 skyBackground(FrameParams f, vec3 dir) {
    float up = clamp(dir.y * 0.5 + 0.5, 0.0, 1.0);
    return f.skyRadiance.rgb * mix(0.6, 1.4, up);
}

#endif
