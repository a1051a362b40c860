#version 460
// Reference path tracer: progressive, over the same grid and lights as every other method.
// Pixel filter: a box over the pixel — each sample traces its own camera ray through a uniformly
// jittered point of the pixel's square (seeded, so the same inputs give the same image), through
// the static world and the dynamic objects (traceScene, as the G-buffer does). The G-buffer is
// not read: one ray through the pixel centre aliases at every edge. (REFERENCE_PIXEL_CENTRE traces
// through the pixel centre, for comparisons with the methods that shade the G-buffer.)
// At each vertex, next-event estimation of the emitters (by power, area sampling, one shadow ray)
// and of the sun, and a cosine-weighted ray that counts the emission of the light it hits (also
// from the last vertex, where it goes no further); the two ways of reaching an emitter are
// combined by multiple importance sampling (power heuristic, Veach & Guibas 1995), so a light
// close to a surface no longer makes fireflies. Continuation rays that escape see the sky;
// Russian roulette after three bounces. With zero bounces it is the direct-light ground truth,
// by light sampling alone as before.
#extension GL_GOOGLE_include_directive : require

#include "common/camera.glsl"
#include "common/direct_light.glsl"
#include "common/emitter_lookup.glsl"
#include "shared/reference.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = REFERENCE_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = REFERENCE_BINDING_PARAMS, std430) readonly buffer Reference { ReferenceParams gReference; };
layout(set = 0, binding = REFERENCE_BINDING_ACCUMULATION, std430) buffer Accumulation { vec4 gAccum[]; };
layout(set = 0, binding = REFERENCE_BINDING_RADIANCE, std430) writeonly buffer Radiance { vec4 gRadiance[]; };

vec3 cosineDirection(vec3 n, float u1, float u2) {
    float r = sqrt(u1), phi = 2.0 * PI * u2;
    vec3 t = abs(n.x) > 0.5 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 b1 = normalize(cross(n, t));
    vec3 b2 = cross(n, b1);
    return normalize(b1 * (r * cos(phi)) + b2 * (r * sin(phi)) + n * sqrt(max(0.0, 1.0 - u1)));
}

// The surface a ray hit, as surfaceFrom reads it from the G-buffer.
Surface surfaceAt(SceneHit hit, vec3 origin, vec3 dir) {
    Surface s;
    s.face = hit.face;
    s.valid = hit.face < 6u;
    s.position = origin + dir * hit.t;
    s.normal = s.valid ? faceNormalF(hit.face) : vec3(0.0);
    GpuMaterial m = gMaterials[hit.material];
    s.albedo = m.albedo.rgb;
    s.emission = m.emission.rgb;
    return s;
}

// Test probe: the emitter derived for the static voxel seen through the pixel centre.
vec4 probeEmitter(uvec2 pixel, uint flags) {
    SceneHit hit = traceScene(gFrame.cameraPosition.xyz, cameraRayDirection(gFrame, pixel), 1.0e30);
    EmitterShape shape;
    if (!hit.hit || hit.dynamicSet || !emitterOfStaticVoxel(hit.voxel, (flags & REFERENCE_BRICK_LIGHTS) != 0u, shape)) {
        return vec4(-1.0);
    }
    if ((flags & REFERENCE_PROBE_EMITTER_SHAPE) != 0u) {
        return vec4(vec3(shape.emitter.minCorner.xyz), float(shape.emitter.info.x | (uint(shape.emitter.minCorner.w) << 6u)));
    }
    return vec4(shape.power, shape.power / gLights.power.x, 0.0, 0.0);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    uint flags = gReference.flags;
    if ((flags & (REFERENCE_PROBE_EMITTER_SHAPE | REFERENCE_PROBE_EMITTER_POWER)) != 0u) {
        gRadiance[index] = probeEmitter(pixel, flags);
        return;
    }
    uint bounces = gReference.bounces;
    // The direct-light reference (no bounces) stays light sampling alone: the ground truth the
    // quadrature test checks, at its old cost.
    const bool mis = (flags & REFERENCE_LIGHT_SAMPLING_ONLY) == 0u && bounces > 0u;
    const bool brickLights = (flags & REFERENCE_BRICK_LIGHTS) != 0u;
    vec4 accum = gAccum[index];
    uint spp = max(gReference.samples, 1u);
    for (uint sampleIndex = 0u; sampleIndex < spp; ++sampleIndex) {
        uint rng = rngInit(pixel, uint(accum.w), 5u, gReference.seed);
        // Box filter: a uniform point of the pixel (or its centre, on request).
        vec2 jitter = vec2(0.5);
        if ((flags & REFERENCE_PIXEL_CENTRE) == 0u) jitter = vec2(rngNext(rng), rngNext(rng));
        vec3 origin = gFrame.cameraPosition.xyz;
        vec3 dir = cameraRayDirectionAt(gFrame, vec2(pixel) + jitter);
        SceneHit hit = traceScene(origin, dir, 1.0e30);
        vec3 L;
        if (!hit.hit) {
            L = skyBackground(gFrame, dir);
        } else {
            Surface s = surfaceAt(hit, origin, dir);
            L = s.emission;
            vec3 throughput = vec3(1.0);
            for (uint bounce = 0u; s.valid; ++bounce) {
                bool last = bounce >= bounces;
                if (!mis) {
                    L += throughput * directLight(s, gFrame, rng);
                    if (last) break;
                } else {
                    L += throughput * directLightMis(s, gFrame, rng);
                }
                // The cosine-sampled ray: the next vertex and, with MIS, the emitter it hits. From
                // the last vertex it only looks for emitters (the second technique for the light
                // sampled there) and sees no sky, as before MIS.
                dir = cosineDirection(s.normal, rngNext(rng), rngNext(rng));
                vec3 from = s.position, fromNormal = s.normal;
                throughput *= s.albedo;  // cosine sampling of a diffuse BRDF: f cos / p = albedo
                if (bounce >= 3u) {
                    float keep = min(max(throughput.r, max(throughput.g, throughput.b)), 0.95);
                    if (rngNext(rng) >= keep) break;
                    throughput /= keep;
                }
                origin = s.position + s.normal * kRayOffset;
                hit = traceScene(origin, dir, 1.0e30);
                if (!hit.hit) {
                    if (!last) L += throughput * skyBackground(gFrame, dir);
                    break;
                }
                s = surfaceAt(hit, origin, dir);
                // Emission found by the cosine ray, weighted against the light sample that could
                // have found it. Only the lights of the emitter list count (an object's emissive
                // voxel lights nothing, in every method).
                EmitterShape shape;
                if (mis && !hit.dynamicSet && s.valid && emitterOfStaticVoxel(hit.voxel, brickLights, shape) &&
                    (shape.emitter.info.x & (1u << hit.face)) != 0u) {
                    // Both weights from the same segment (vertex to light point) as directLightMis
                    // measures it, so the two weights of every path sum to one.
                    vec3 segment = s.position - from;
                    float dist = length(segment);
                    vec3 toLight = segment / dist;
                    float lightPdf = lightSamplePdfSolidAngle(shape, hit.face, from, dist, toLight);
                    float bsdfPdf = max(dot(fromNormal, toLight), 0.0) / PI;
                    L += throughput * s.emission * powerHeuristic(bsdfPdf, lightPdf);
                }
                if (last) break;
            }
        }
        accum += vec4(L, 1.0);
    }
    gAccum[index] = accum;
    gRadiance[index] = vec4(accum.rgb / accum.w, 1.0);
}
