// Reading the G-buffer back as a shading surface.
#ifndef COMMON_SURFACE_GLSL
#define COMMON_SURFACE_GLSL

#include "common/emitters.glsl"
#include "shared/frame_params.h"
#include "shared/gbuffer.h"

// A GBufferTexel from an R32G32B32A32_UINT view of the G-buffer, four texels per pixel. The passes
// that only read the G-buffer bind it so: a texel fetch is one gather for the SIMD batch on llvmpipe,
// a storage-buffer read at a lane-varying index a loop over the lanes (docs/PERFORMANCE.md). Fields
// a caller does not use cost no fetch (the compiler drops it).
GBufferTexel loadGBuffer(usamplerBuffer texels, uint i) {
    int t = int(i) * 4;
    return GBufferTexel(ivec4(texelFetch(texels, t)), texelFetch(texels, t + 1), uintBitsToFloat(texelFetch(texels, t + 2)),
                        uintBitsToFloat(texelFetch(texels, t + 3)));
}

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
