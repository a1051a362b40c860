#version 460
// ReSTIR spatial reuse (thesis §4.6): merge this pixel's own reservoir (after temporal reuse) with
// the fresh candidate reservoirs of k random pixels in an r-pixel disc that see a similar surface
// (depth within the tolerance, same face normal).
//
// Why fresh candidates and not the neighbours' reuse results: a reservoir that went through a
// shadow test (the candidate test, or last frame's shading) targets the light *visible at its own
// pixel*. Reused at another pixel, its occluded samples count in M but can never be chosen, so
// light visible here but not there is lost; fed back through temporal reuse, that loss compounds
// frame after frame towards the M cap (it cost 12-47 % of the light). A neighbour's candidates are
// drawn from the unshadowed target, whose support each neighbour knows exactly, so counting the M
// of the inputs whose target is positive for the chosen sample (Bitterli et al. 2020, Alg. 6)
// gives an unbiased weight for every sample visible here, without a shadow ray per neighbour.
// Samples occluded here contribute nothing when shaded, whatever their weight.
//
// The unbiased mode weighs the same inputs by pairwise MIS instead (see pairwiseReuse): same
// target evaluations, no shadow ray, bounded weights for a neighbour's sample that is worth far
// more here than there (docs/ACCURACY.md measures what that buys).
#extension GL_GOOGLE_include_directive : require

#include "common/reservoir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = FEATURE_UNBIASED) const bool kUnbiased = true;  // pairwise MIS compiled in

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;  // loadGBuffer
layout(set = 0, binding = RESTIR_SPATIAL_BINDING_OWN) uniform usamplerBuffer gOwn;  // loadReservoir
layout(set = 0, binding = RESTIR_SPATIAL_BINDING_CANDIDATES) uniform usamplerBuffer gCandidates;
layout(set = 0, binding = RESTIR_SPATIAL_BINDING_OUT, std430) writeonly buffer Out { Reservoir gOut[]; };

const uint kMaxTaps = 16u;

// Pairwise MIS with confidence weights (Bitterli's 2022 thesis, "Correlations and reuse for fast
// and accurate physically based light transport", eq. 9.10; Lin et al. 2022; Wyman et al. 2023,
// "A gentle introduction to ReSTIR", pairwise MIS): this pixel's own reservoir is the canonical
// input c, whose support is every sample visible here. Its confidence M_c is split into k equal
// parts, one per neighbour i; the pair (i, c) gets the share (M_i + M_c/k) / (M_c + sum M_j) and
// divides it by the balance heuristic between M_i p_i and (M_c/k) p_c. The weights of every sample
// then sum to one (each pair's two weights sum to its share; a pair whose neighbour cannot produce
// the sample gives its whole share to c), and where the targets agree they are M_i / sum M, as in
// the default mode. Each neighbour costs two target evaluations (its sample here, the canonical
// sample there) and no shadow ray: neighbours' candidate reservoirs are unshadowed, so their
// support is exactly where their target is positive, and nothing about visibility at a
// neighbour enters the weights. (Reusing shadow-tested reservoirs would need it.)
Reservoir pairwiseReuse(Surface s, Reservoir own, float ownChooser, uint neighbours[kMaxTaps], float choosers[kMaxTaps],
                        uint k) {
    if (k == 0u) return own;
    float ownM = own.weights.y;
    float total = ownM;
    for (uint i = 0u; i < k; ++i) total += loadReservoir(gCandidates, neighbours[i]).weights.y;
    if (!(total > 0.0)) return own;
    float ownShare = ownM / float(k);  // the canonical's confidence in each pair
    bool ownSample = reservoirHasLight(own) && own.weights.x > 0.0;
    float ownTarget = ownSample ? own.weights.z : 0.0;  // evaluated here by the earlier passes

    Combiner c = combinerStart();
    float ownWeight = 0.0;
    for (uint i = 0u; i < k; ++i) {
        Reservoir r = loadReservoir(gCandidates, neighbours[i]);
        float m = r.weights.y;
        float pairShare = (m + ownShare) / total;
        float targetThere = reservoirHasLight(r) ? r.weights.z : 0.0;  // its sample at its own pixel
        float targetHere = targetAt(s, r);
        combinerAddWeighted(c, r, targetHere, pairShare * balanceShare(m, targetThere, ownShare, targetHere), choosers[i]);
        if (ownSample) {
            float ownTargetThere = targetAt(surfaceFrom(loadGBuffer(gGBuffer, neighbours[i])), own);
            ownWeight += pairShare * balanceShare(ownShare, ownTarget, m, ownTargetThere);
        }
    }
    combinerAddWeighted(c, own, ownTarget, ownWeight, ownChooser);
    return combinerFinish(c, 1.0);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    // Without temporal reuse the own reservoir is the candidates' one: apply its shadow test.
    Reservoir own = withOwnVisibility(loadReservoir(gOwn, index));
    GBufferTexel g = loadGBuffer(gGBuffer, index);
    Surface s = surfaceFrom(g);
    if (!s.valid || gRestir.knobs.spatial == 0u) {
        gOut[index] = own;
        return;
    }
    float depth = gbufferDistance(g);
    uint rng = rngInit(pixel, gRestir.frameIndex, 3u, gRestir.seed);
    uint taps = min(gRestir.knobs.spatialTaps, kMaxTaps);
    float radius = gRestir.knobs.spatialRadius;
    float tolerance = gRestir.knobs.depthTolerance;

    bool pairwise = kUnbiased && gRestir.knobs.unbiased != 0u;
    Combiner c = combinerStart();
    // weights.z already holds the own sample's target here (the candidate and temporal passes
    // evaluated it at this surface this frame): no need to evaluate it again.
    float ownChooser = rngNext(rng);
    if (!pairwise) combinerAdd(c, own, reservoirHasLight(own) ? own.weights.z : 0.0, ownChooser);
    uint neighbours[kMaxTaps];
    float choosers[kMaxTaps];
    uint accepted = 0u;
    for (uint i = 0u; i < taps; ++i) {
        float angle = 2.0 * PI * rngNext(rng);
        float dist = radius * sqrt(rngNext(rng));
        float u = rngNext(rng);
        ivec2 q = ivec2(pixel) + ivec2(round(dist * vec2(cos(angle), sin(angle))));
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(gFrame.imageSize.xy))) || q == ivec2(pixel)) continue;
        uint qi = uint(q.x) + uint(q.y) * gFrame.imageSize.x;
        GBufferTexel ng = loadGBuffer(gGBuffer, qi);
        if (uint(ng.voxel.w) != s.face || abs(gbufferDistance(ng) - depth) > tolerance * depth) continue;
        if (!pairwise) {
            Reservoir r = loadReservoir(gCandidates, qi);
            combinerAdd(c, r, targetAt(s, r), u);
        }
        choosers[accepted] = u;
        neighbours[accepted++] = qi;
    }
    if (pairwise) {
        gOut[index] = pairwiseReuse(s, own, ownChooser, neighbours, choosers, accepted);
        return;
    }

    // This pixel could have produced any sample with a positive target here (every chosen one);
    // a neighbour only those with a positive target at its own surface.
    float normaliser = own.weights.y;
    if (reservoirHasLight(c.chosen)) {
        for (uint i = 0u; i < accepted; ++i) {
            if (targetAt(surfaceFrom(loadGBuffer(gGBuffer, neighbours[i])), c.chosen) > 0.0) normaliser += loadReservoir(gCandidates, neighbours[i]).weights.y;
        }
    } else {
        normaliser = c.M;
    }
    gOut[index] = combinerFinish(c, normaliser);
}
