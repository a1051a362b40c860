#version 460
// ReSTIR temporal reuse (thesis §4.4 and §4.9): merge this pixel's candidate reservoir with last
// frame's final reservoir at the motion-vector pixel, if that pixel saw the same surface (depth
// within the tolerance, same face normal); last frame's M is capped at `cap` x this frame's.
// The result is this pixel's own reservoir for spatial reuse; the candidates stay untouched, since
// neighbours reuse them as they were drawn (see spatial_reuse.comp).
// The default mode normalises by the M of both inputs, which is right while last frame's surface is
// this one's (a still camera); the unbiased mode weighs them by the balance heuristic (see
// balancedReuse), which stays right when the camera moves.
#extension GL_GOOGLE_include_directive : require

#include "common/reservoir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = FEATURE_UNBIASED) const bool kUnbiased = true;  // the balance heuristic compiled in

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;  // loadGBuffer
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_PREV_GBUFFER) uniform usamplerBuffer gPrevGBuffer;
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_CANDIDATES) uniform usamplerBuffer gCandidates;  // loadReservoir
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_PREVIOUS) uniform usamplerBuffer gPrevious;
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_OWN, std430) writeonly buffer Own { Reservoir gOwn[]; };

// Last frame's reservoir for this pixel, or an empty one when there is none to reuse.
bool previousReservoir(uvec2 pixel, GBufferTexel g, Surface s, out Reservoir previous, out GBufferTexel pg) {
    previous = emptyReservoir();
    pg = g;
    if (!s.valid || g.motion.w == 0.0) return false;
    ivec2 prevPixel = ivec2(floor(g.motion.xy));
    if (any(lessThan(prevPixel, ivec2(0))) || any(greaterThanEqual(prevPixel, ivec2(gFrame.imageSize.xy)))) return false;
    uint prevIndex = uint(prevPixel.x) + uint(prevPixel.y) * gFrame.imageSize.x;
    pg = loadGBuffer(gPrevGBuffer, prevIndex);
    if (uint(pg.voxel.w) != s.face || abs(gbufferDistance(pg) - g.motion.z) > gRestir.knobs.depthTolerance * g.motion.z) return false;
    previous = loadReservoir(gPrevious, prevIndex);
    return !reservoirStale(previous);  // a light that is gone: drop it
}

// The unbiased mode: generalized RIS over this pixel's candidates c and last frame's reservoir p,
// weighted by the balance heuristic with their confidences (pairwise MIS with one neighbour; Lin et
// al. 2022): m_c(y) = M_c p_c(y) / (M_c p_c(y) + M_p p_p(y) V_p(y)) and m_p = 1 - m_c. Last frame's
// reservoir only holds samples visible from its surface (shade.comp zeroes the others), hence V_p:
// the candidates' own sample needs one shadow ray from last frame's surface, unless that surface is
// this one (the same point: a still camera), where it sees what this pixel sees. Last frame's
// sample needs none: it was visible there, and if it is occluded here it is shaded as zero.
// (V_p is tested in this frame's world: an occluder that moved since then is the one residual.)
Reservoir balancedReuse(Surface s, GBufferTexel g, Reservoir current, Reservoir previous, GBufferTexel pg, float uCurrent,
                        float uPrevious) {
    Surface prevSurface = surfaceFrom(pg);
    float mCurrent = current.weights.y, mPrevious = previous.weights.y;
    float currentTarget = reservoirHasLight(current) ? current.weights.z : 0.0;
    float currentWeight = 0.0;
    if (currentTarget > 0.0 && current.weights.x > 0.0) {
        float targetThere = targetAt(prevSurface, current);
        bool samePoint = all(equal(pg.position.xyz, g.position.xyz)) && pg.voxel.w == g.voxel.w;
        if (targetThere > 0.0 && !samePoint && !visibleAt(prevSurface, current)) targetThere = 0.0;
        currentWeight = balanceShare(mCurrent, currentTarget, mPrevious, targetThere);
    }
    // Last frame's sample at its own surface (stored there) and here.
    float previousThere = reservoirHasLight(previous) ? previous.weights.z : 0.0;
    float previousHere = targetAt(s, previous);
    Combiner c = combinerStart();
    combinerAddWeighted(c, current, currentTarget, currentWeight, uCurrent);
    combinerAddWeighted(c, previous, previousHere, balanceShare(mPrevious, previousThere, mCurrent, previousHere), uPrevious);
    return combinerFinish(c, 1.0);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = loadGBuffer(gGBuffer, index);
    Surface s = surfaceFrom(g);
    // This pixel's candidates with their shadow test applied: like last frame's final reservoir
    // (whose occluded sample lost its weight in shade.comp), they now target the visible light here.
    Reservoir current = withOwnVisibility(loadReservoir(gCandidates, index));
    Reservoir previous;
    GBufferTexel pg;
    if (!previousReservoir(pixel, g, s, previous, pg)) {
        gOwn[index] = current;
        return;
    }
    previous.weights.y = min(previous.weights.y, gRestir.knobs.temporalCap * float(gRestir.knobs.candidates));

    uint rng = rngInit(pixel, gRestir.frameIndex, 2u, gRestir.seed);
    if (kUnbiased && gRestir.knobs.unbiased != 0u) {
        float uCurrent = rngNext(rng);
        gOwn[index] = balancedReuse(s, g, current, previous, pg, uCurrent, rngNext(rng));
        return;
    }
    Combiner c = combinerStart();
    float targetCurrent = reservoirHasLight(current) ? current.weights.z : 0.0;
    combinerAdd(c, current, targetCurrent, rngNext(rng));
    combinerAdd(c, previous, targetAt(s, previous), rngNext(rng));

    gOwn[index] = combinerFinish(c, c.M);
}
