#version 460
// Final shading for the reservoir-based methods: emission + sun + the reservoir's light sample
// with one shadow ray, weighted by its contribution weight W. A reservoir whose light was
// removed or replaced is never shaded.
#extension GL_GOOGLE_include_directive : require

#include "common/camera.glsl"
#include "common/reservoir.glsl"
#include "common/ray_sort.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
// Read and written: a sample found occluded here keeps its M but loses its weight, so the
// reservoir the next frame reuses agrees with its visibility (Bitterli et al. 2020 §4.4 and §6).
layout(set = 0, binding = RESTIR_SHADE_BINDING_FINAL, std430) buffer Final { Reservoir gFinal[]; };
layout(set = 0, binding = RESTIR_SHADE_BINDING_RADIANCE, std430) writeonly buffer Radiance { vec4 gRadiance[]; };

void main() {
    // No early return: every invocation of the workgroup takes part in the two sorted shadow rays.
    uvec2 pixel = gl_GlobalInvocationID.xy;
    bool inside = all(lessThan(pixel, gFrame.imageSize.xy));
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g;
    Surface s = Surface(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), FACE_NONE, false);
    if (inside) {
        g = gGBuffer[index];
        s = surfaceFrom(g);
    }
    bool lit = inside && s.valid;

    // The sun: sunLight (common/surface.glsl) with its ray traced sorted.
    vec3 sunDir = gFrame.sunDirection.xyz;
    float cosine = dot(s.normal, sunDir);
    bool sunRay = lit && cosine > 0.0 && any(greaterThan(gFrame.sunRadiance.rgb, vec3(0.0)));
    SceneHit sunHit = traceSceneSorted(sunRay, s.position + s.normal * kRayOffset, sunDir, 1.0e30);
    vec3 sun = sunRay && !sunHit.hit ? s.albedo / PI * gFrame.sunRadiance.rgb * cosine : vec3(0.0);

    // The reservoir's light.
    Reservoir r;
    bool shaded = false;
    if (lit) {
        r = gFinal[index];
        shaded = emitterCurrent(r.light.x, r.light.y) && r.weights.x > 0.0;
    }
    GpuEmitter e;  // read only when shaded
    vec3 f = vec3(0.0);
    vec3 toLight = vec3(0.0, 0.0, 1.0);
    float dist = 0.0;
    if (shaded) {
        e = gEmitters[r.light.x];
        f = lightContribution(s, e, r.light.z, unpackUnorm2x16(r.light.w), toLight, dist);
    }
    bool lightRay = shaded && any(greaterThan(f, vec3(0.0)));
    bool visible = lightVisibleSorted(lightRay, s, e, toLight, dist);

    if (!inside) return;
    if (uint(g.voxel.w) == FACE_NONE) {
        gRadiance[index] = vec4(skyBackground(gFrame, cameraRayDirection(gFrame, pixel)), 1.0);
        return;
    }
    vec3 radiance = s.emission;
    if (lit) {
        radiance += sun;
        if (lightRay && visible) {
            radiance += f * r.weights.x;
        } else if (shaded) {
            gFinal[index].weights.x = 0.0;
        }
    }
    gRadiance[index] = vec4(radiance, 1.0);
}
