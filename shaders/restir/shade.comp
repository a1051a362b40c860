#version 460
// Final shading for the reservoir-based methods: emission + sun + the reservoir's light sample
// with one shadow ray, weighted by its contribution weight W. A reservoir whose light was
// removed or replaced is never shaded.
#extension GL_GOOGLE_include_directive : require

#include "common/camera.glsl"
#include "common/reservoir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;  // loadGBuffer
// Read and written: a sample found occluded here keeps its M but loses its weight, so the
// reservoir the next frame reuses agrees with its visibility (Bitterli et al. 2020 §4.4 and §6).
layout(set = 0, binding = RESTIR_SHADE_BINDING_FINAL, std430) buffer Final { Reservoir gFinal[]; };
layout(set = 0, binding = RESTIR_SHADE_BINDING_RADIANCE, std430) writeonly buffer Radiance { vec4 gRadiance[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = loadGBuffer(gGBuffer, index);
    Surface s = surfaceFrom(g);
    if (uint(g.voxel.w) == FACE_NONE) {
        gRadiance[index] = vec4(skyBackground(gFrame, cameraRayDirection(gFrame, pixel)), 1.0);
        return;
    }
    vec3 radiance = s.emission;
    if (s.valid) {
        radiance += sunLight(s, gFrame);
        Reservoir r = gFinal[index];
        if (emitterCurrent(r.light.x, r.light.y) && r.weights.x > 0.0) {
            GpuEmitter e = loadEmitter(r.light.x);
            vec3 toLight;
            float dist;
            vec3 f = lightContribution(s, e, r.light.z, unpackUnorm2x16(r.light.w), toLight, dist);
            if (any(greaterThan(f, vec3(0.0))) && lightVisible(s, e, toLight, dist)) {
                radiance += f * r.weights.x;
            } else {
                gFinal[index].weights.x = 0.0;
            }
        }
    }
    gRadiance[index] = vec4(radiance, 1.0);
}
