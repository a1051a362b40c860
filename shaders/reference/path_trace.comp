#version 460
// Reference path tracer: progressive, over the same grid and lights as every other method. At
// each vertex, next-event estimation of the emitters (by power, area sampling, one shadow ray)
// and of the sun; bounces are cosine-weighted, rays that escape see the sky; Russian roulette
// after three bounces. With zero bounces it is the direct-light ground truth.
#extension GL_GOOGLE_include_directive : require

#include "common/camera.glsl"
#include "common/direct_light.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 0, std430) readonly buffer Params { FrameParams gFrame; };
// seeds.x: seed, seeds.y: samples per pixel in this dispatch, seeds.z: bounces
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 1, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 2, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 3, std430) buffer Accumulation { vec4 gAccum[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 4, std430) writeonly buffer Radiance { vec4 gRadiance[]; };

vec3 cosineDirection(vec3 n, float u1, float u2) {
    float r = sqrt(u1), phi = 2.0 * PI * u2;
    vec3 t = abs(n.x) > 0.5 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 b1 = normalize(cross(n, t));
    vec3 b2 = cross(n, b1);
    return normalize(b1 * (r * cos(phi)) + b2 * (r * sin(phi)) + n * sqrt(max(0.0, 1.0 - u1)));
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = gGBuffer[index];
    Surface primary = surfaceFrom(g);
    vec4 accum = gAccum[index];
    uint spp = max(gRestir.seeds.y, 1u);
    uint bounces = gRestir.seeds.z;
    for (uint sampleIndex = 0u; sampleIndex < spp; ++sampleIndex) {
        vec3 L = vec3(0.0);
        if (uint(g.voxel.w) == FACE_NONE) {
            L = skyBackground(gFrame, cameraRayDirection(gFrame, pixel));
        } else {
            uint rng = rngInit(pixel, uint(accum.w), 5u, gRestir.seeds.x);
            L = primary.emission;
            Surface s = primary;
            vec3 throughput = vec3(1.0);
            for (uint bounce = 0u; s.valid; ++bounce) {
                L += throughput * directLight(s, gFrame, rng);
                if (bounce >= bounces) break;
                vec3 dir = cosineDirection(s.normal, rngNext(rng), rngNext(rng));
                throughput *= s.albedo;  // cosine sampling of a diffuse BRDF: f cos / p = albedo
                if (bounce >= 3u) {
                    float keep = min(max(throughput.r, max(throughput.g, throughput.b)), 0.95);
                    if (rngNext(rng) >= keep) break;
                    throughput /= keep;
                }
                vec3 origin = s.position + s.normal * kRayOffset;
                SceneHit hit = traceScene(origin, dir, 1.0e30);
                if (!hit.hit) {
                    L += throughput * skyBackground(gFrame, dir);
                    break;
                }
                s.face = hit.face;
                s.valid = hit.face < 6u;
                s.position = origin + dir * hit.t;
                s.normal = s.valid ? faceNormalF(hit.face) : vec3(0.0);
                s.albedo = gMaterials[hit.material].albedo.rgb;
            }
        }
        accum += vec4(L, 1.0);
    }
    gAccum[index] = accum;
    gRadiance[index] = vec4(accum.rgb / accum.w, 1.0);
}
