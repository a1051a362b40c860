#version 460
// One edge-stopped a-trous pass of the denoiser (Dammertz et al. 2010, "Edge-Avoiding A-Trous
// Wavelet Transform for fast Global Illumination Filtering"; variance-guided as in Schied et al.
// 2017): a 3x3 B-spline kernel with taps `step` pixels apart, each tap weighted by whether it
// sees the same surface plane (exact, common/surface_key.glsl: no blur across voxel edges) and
// by how far its luminance is from this pixel's in standard deviations of the signal. The last
// pass multiplies the albedo back and adds the emission into the frame's radiance.
#extension GL_GOOGLE_include_directive : require

#include "common/surface.glsl"
#include "common/surface_key.glsl"
#include "shared/denoiser.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = DENOISER_ATROUS_BINDING_FRAME, std430) readonly buffer Frame { FrameParams gFrame; };
layout(set = 0, binding = DENOISER_ATROUS_BINDING_PARAMS, std430) readonly buffer Params { DenoiserParams gParams; };
layout(set = 0, binding = DENOISER_ATROUS_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;
layout(set = 0, binding = DENOISER_ATROUS_BINDING_RADIANCE, std430) buffer Radiance { vec4 gRadiance[]; };
// The input is read at the taps' indices: as texels (one gather per tap on lavapipe).
layout(set = 0, binding = DENOISER_ATROUS_BINDING_INPUT) uniform samplerBuffer gInput;
layout(set = 0, binding = DENOISER_ATROUS_BINDING_OUTPUT, std430) writeonly buffer Output { vec4 gOutput[]; };
layout(set = 0, binding = DENOISER_ATROUS_BINDING_SURFACE_KEYS) uniform usamplerBuffer gSurfaceKeys;


void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = gFrame.imageSize.xy;
    if (any(greaterThanEqual(pixel, size))) return;
    uint index = pixel.x + pixel.y * size.x;
    // The keys primary rays wrote: a uint per tap; the G-buffer only for the remodulation.
    uint key = texelFetch(gSurfaceKeys, int(index)).x;
    if (key == SURFACE_KEY_SKY) return;  // the radiance keeps the sky

    vec4 centre = texelFetch(gInput, int(index));
    float lum = luminance(centre.rgb);
    const float kernel[3] = float[3](0.25, 0.5, 0.25);
    int step = int(gParams.step);
    // Luminance edges count in standard deviations of the signal; a converged signal keeps them.
    // The deviation is the plane's 3x3 neighbourhood's (Schied et al. 2017 prefilter it too): a
    // pixel's own variance rises and falls with its own noise, and a bright sample that widened
    // its own edges while a dark one narrowed them took light out of the image (Denoiser.KeepsTheEnergy).
    float varianceNear = 0.0, weightNear = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = ivec2(pixel) + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(size)))) continue;
            uint qi = uint(q.x) + uint(q.y) * size.x;
            if (qi != index && texelFetch(gSurfaceKeys, int(qi)).x != key) continue;
            float w = kernel[dx + 1] * kernel[dy + 1];
            varianceNear += texelFetch(gInput, int(qi)).a * w;
            weightNear += w;
        }
    }
    float sigma = 4.0 * sqrt(max(varianceNear / weightNear, 0.0)) + 1.0e-4;
    vec3 sum = vec3(0.0);
    float weightSum = 0.0, varianceSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = ivec2(pixel) + ivec2(dx, dy) * step;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(size)))) continue;
            uint qi = uint(q.x) + uint(q.y) * size.x;
            vec4 c = texelFetch(gInput, int(qi));
            if (qi != index && texelFetch(gSurfaceKeys, int(qi)).x != key) continue;
            float w = kernel[dx + 1] * kernel[dy + 1] * exp(-abs(luminance(c.rgb) - lum) / sigma);
            sum += c.rgb * w;
            weightSum += w;
            varianceSum += c.a * w * w;
        }
    }
    vec4 filtered = vec4(sum / weightSum, varianceSum / (weightSum * weightSum));
    gOutput[index] = filtered;
    if ((gParams.flags & DENOISER_LAST) != 0u) {
        Surface s = surfaceFrom(loadGBuffer(gGBuffer, index));
        gRadiance[index] = vec4(s.emission + max(s.albedo, vec3(DENOISER_MIN_ALBEDO)) * filtered.rgb, 1.0);
    }
}
