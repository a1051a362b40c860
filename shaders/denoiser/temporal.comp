#version 460
// The denoiser's temporal step (after Schied et al. 2017, "Spatiotemporal Variance-Guided
// Filtering"): the lighting with the albedo divided out (so texture is not blurred and comes back
// sharp), averaged with last frame's mean at the point this pixel's surface was then (the
// G-buffer's motion vector), over history texels that saw the same surface plane
// (common/surface_key.glsl; last frame's keys as primary rays wrote them). Per pixel it keeps the
// mean, its frame count and the first two moments of luminance, and writes the signal with its
// variance for the a-trous passes.
#extension GL_GOOGLE_include_directive : require

#include "common/surface.glsl"
#include "common/surface_key.glsl"
#include "shared/denoiser.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = DENOISER_BINDING_FRAME, std430) readonly buffer Frame { FrameParams gFrame; };
layout(set = 0, binding = DENOISER_BINDING_PARAMS, std430) readonly buffer Params { DenoiserParams gParams; };
layout(set = 0, binding = DENOISER_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;
layout(set = 0, binding = DENOISER_BINDING_PREV_SURFACE_KEYS) uniform usamplerBuffer gPrevSurfaceKeys;
layout(set = 0, binding = DENOISER_BINDING_RADIANCE, std430) readonly buffer Radiance { vec4 gRadiance[]; };
// Last frame's history is read at other pixels' indices: as texels (one gather per tap on
// lavapipe, where a storage-buffer read at a lane-varying index is a loop over the lanes).
layout(set = 0, binding = DENOISER_BINDING_PREV_HISTORY) uniform samplerBuffer gPrevHistory;
layout(set = 0, binding = DENOISER_BINDING_HISTORY, std430) writeonly buffer History { vec4 gHistory[]; };
layout(set = 0, binding = DENOISER_BINDING_PREV_MOMENTS) uniform samplerBuffer gPrevMoments;
layout(set = 0, binding = DENOISER_BINDING_MOMENTS, std430) writeonly buffer Moments { vec2 gMoments[]; };
layout(set = 0, binding = DENOISER_BINDING_FILTERED, std430) writeonly buffer Filtered { vec4 gFiltered[]; };


void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = gFrame.imageSize.xy;
    if (any(greaterThanEqual(pixel, size))) return;
    uint index = pixel.x + pixel.y * size.x;
    GBufferTexel g = loadGBuffer(gGBuffer, index);
    Surface s = surfaceFrom(g);
    if (!s.valid) {  // sky: nothing to denoise
        gHistory[index] = vec4(0.0);
        gMoments[index] = vec2(0.0);
        gFiltered[index] = vec4(0.0);
        return;
    }
    vec3 albedo = max(s.albedo, vec3(DENOISER_MIN_ALBEDO));
    vec3 signal = max(gRadiance[index].rgb - s.emission, vec3(0.0)) / albedo;

    // Last frame's mean where this surface point was: bilinear over the four history texels
    // around it (texel i's sample sat at i + 0.5 + last frame's jitter), each only if it saw the
    // same surface plane.
    vec4 history = vec4(0.0);
    vec2 moments = vec2(0.0);
    float weight = 0.0;
    if ((gParams.flags & DENOISER_RESTART) == 0u && g.motion.w > 0.0) {
        uint key = surfaceKey(g);
        vec2 p = g.motion.xy - 0.5 - gFrame.jitter.zw;
        ivec2 base = ivec2(floor(p));
        vec2 f = p - vec2(base);
        // A still view: the point was in this very pixel, only the jitter moved its sample. The
        // pixel's own history is its average over the pixel; a bilinear read would mix in its
        // neighbours every frame (the jitter's difference, up to a pixel), and that blur adds up.
        // (Where this pixel saw another plane last frame, the bilinear read may still find it.)
        vec2 here = vec2(pixel) + 0.5 + gFrame.jitter.xy;
        if (all(lessThan(abs(g.motion.xy - here), vec2(1.0e-3))) &&
            texelFetch(gPrevSurfaceKeys, int(index)).x == key) {
            base = ivec2(pixel);
            f = vec2(0.0);
        }
        for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) {
                ivec2 q = base + ivec2(dx, dy);
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(size)))) continue;
                uint qi = uint(q.x) + uint(q.y) * size.x;
                if (texelFetch(gPrevSurfaceKeys, int(qi)).x != key) continue;
                float w = (dx == 0 ? 1.0 - f.x : f.x) * (dy == 0 ? 1.0 - f.y : f.y);
                history += texelFetch(gPrevHistory, int(qi)) * w;
                moments += texelFetch(gPrevMoments, int(qi)).xy * w;
                weight += w;
            }
        }
    }
    float frames = 1.0;
    vec3 mean = signal;
    float lum = luminance(signal);
    vec2 m = vec2(lum, lum * lum);
    if (weight > 1.0e-3) {
        history /= weight;
        moments /= weight;
        frames = min(history.w + 1.0, float(gParams.maxHistory));
        float a = 1.0 / frames;
        mean = mix(history.rgb, signal, a);
        m = mix(moments, m, a);
    }
    gHistory[index] = vec4(mean, frames);
    gMoments[index] = m;
    // The variance of the mean: the samples' variance over the frames in it. Few frames say little
    // about it, so a young history is taken as noisy as its own luminance (the filter blurs it
    // within its plane until the frames come in).
    float variance = frames < 4.0 ? lum * lum + 1.0e-4 : max(m.y - m.x * m.x, 0.0) / frames;
    gFiltered[index] = vec4(mean, variance);
}
