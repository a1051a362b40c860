#version 460
// ReSTIR spatial reuse (thesis §4.6): merge this pixel's reservoir with those of k random pixels
// in an r-pixel disc that see a similar surface (depth within the tolerance, same face normal).
#extension GL_GOOGLE_include_directive : require

#include "common/reservoir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 0, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 1, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 2, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 3, std430) readonly buffer In { Reservoir gIn[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 4, std430) writeonly buffer Out { Reservoir gOut[]; };

const uint kMaxTaps = 16u;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    Reservoir own = gIn[index];
    GBufferTexel g = gGBuffer[index];
    Surface s = surfaceFrom(g);
    if (!s.valid || (gRestir.config.y & RESTIR_SPATIAL) == 0u) {
        gOut[index] = own;
        return;
    }
    float depth = gbufferDistance(g);
    uint rng = rngInit(pixel, gRestir.config.w, 3u, gRestir.seeds.x);
    uint taps = min(gRestir.config.z, kMaxTaps);
    float radius = gRestir.reuse.x;
    float tolerance = gRestir.reuse.z;

    Combiner c = combinerStart();
    combinerAdd(c, own, reservoirHasLight(own) ? targetAt(s, own) : 0.0, rngNext(rng));
    uint neighbours[kMaxTaps];
    uint accepted = 0u;
    for (uint i = 0u; i < taps; ++i) {
        float angle = 2.0 * PI * rngNext(rng);
        float dist = radius * sqrt(rngNext(rng));
        float u = rngNext(rng);
        ivec2 q = ivec2(pixel) + ivec2(round(dist * vec2(cos(angle), sin(angle))));
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(gFrame.imageSize.xy))) || q == ivec2(pixel)) continue;
        uint qi = uint(q.x) + uint(q.y) * gFrame.imageSize.x;
        GBufferTexel ng = gGBuffer[qi];
        if (uint(ng.voxel.w) != s.face || abs(gbufferDistance(ng) - depth) > tolerance * depth) continue;
        Reservoir r = gIn[qi];
        if (reservoirStale(r)) continue;
        combinerAdd(c, r, targetAt(s, r), u);
        neighbours[accepted++] = qi;
    }

    float normaliser = c.M;
    if ((gRestir.config.y & RESTIR_UNBIASED) != 0u && reservoirHasLight(c.chosen)) {
        // Bitterli Alg. 6 with visibility: count each input whose pixel could have produced the
        // chosen sample (positive target and visible there); this pixel always could.
        normaliser = own.weights.y;
        for (uint i = 0u; i < accepted; ++i) {
            Surface ns = surfaceFrom(gGBuffer[neighbours[i]]);
            if (targetAt(ns, c.chosen) > 0.0 && visibleAt(ns, c.chosen)) normaliser += gIn[neighbours[i]].weights.y;
        }
    }
    gOut[index] = combinerFinish(c, normaliser);
}
