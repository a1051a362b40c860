#version 460
// ReSTIR temporal reuse (thesis §4.4 and §4.9): merge this pixel's candidate reservoir with last
// frame's final reservoir at the motion-vector pixel, if that pixel saw the same surface (depth
// within the tolerance, same face normal); last frame's M is capped at `cap` x this frame's.
// The result is this pixel's own reservoir for spatial reuse; the candidates stay untouched, since
// neighbours reuse them as they were drawn (see spatial_reuse.comp).
#extension GL_GOOGLE_include_directive : require

#include "common/reservoir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_PREV_GBUFFER, std430) readonly buffer PrevGBuffer { GBufferTexel gPrevGBuffer[]; };
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_CANDIDATES, std430) readonly buffer Candidates { Reservoir gCandidates[]; };
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_PREVIOUS, std430) readonly buffer Previous { Reservoir gPrevious[]; };
layout(set = 0, binding = RESTIR_TEMPORAL_BINDING_OWN, std430) writeonly buffer Own { Reservoir gOwn[]; };

// Last frame's reservoir for this pixel, or an empty one when there is none to reuse.
bool previousReservoir(uvec2 pixel, GBufferTexel g, Surface s, out Reservoir previous, out GBufferTexel pg) {
    previous = emptyReservoir();
    pg = g;
    if (!s.valid || g.motion.w == 0.0) return false;
    ivec2 prevPixel = ivec2(floor(g.motion.xy));
    if (any(lessThan(prevPixel, ivec2(0))) || any(greaterThanEqual(prevPixel, ivec2(gFrame.imageSize.xy)))) return false;
    uint prevIndex = uint(prevPixel.x) + uint(prevPixel.y) * gFrame.imageSize.x;
    pg = gPrevGBuffer[prevIndex];
    if (uint(pg.voxel.w) != s.face || abs(gbufferDistance(pg) - g.motion.z) > gRestir.knobs.depthTolerance * g.motion.z) return false;
    previous = gPrevious[prevIndex];
    return !reservoirStale(previous);  // a light that is gone: drop it
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = gGBuffer[index];
    Surface s = surfaceFrom(g);
    // This pixel's candidates with their shadow test applied: like last frame's final reservoir
    // (whose occluded sample lost its weight in shade.comp), they now target the visible light here.
    Reservoir current = withOwnVisibility(gCandidates[index]);
    Reservoir previous;
    GBufferTexel pg;
    if (!previousReservoir(pixel, g, s, previous, pg)) {
        gOwn[index] = current;
        return;
    }
    previous.weights.y = min(previous.weights.y, gRestir.knobs.temporalCap * float(gRestir.knobs.candidates));

    uint rng = rngInit(pixel, gRestir.frameIndex, 2u, gRestir.seed);
    Combiner c = combinerStart();
    float targetCurrent = reservoirHasLight(current) ? current.weights.z : 0.0;
    combinerAdd(c, current, targetCurrent, rngNext(rng));
    combinerAdd(c, previous, targetAt(s, previous), rngNext(rng));

    float normaliser = c.M;
    if (gRestir.knobs.unbiased != 0u) {
        // Count only the inputs whose pixel could have produced the chosen sample: its target
        // there is positive and, for the other pixel, the sample is visible from it.
        Surface prevSurface = surfaceFrom(pg);
        // This pixel always could (the chosen sample has a positive target here).
        normaliser = current.weights.y;
        if (reservoirHasLight(c.chosen) && targetAt(prevSurface, c.chosen) > 0.0 && visibleAt(prevSurface, c.chosen))
            normaliser += previous.weights.y;
    }
    gOwn[index] = combinerFinish(c, normaliser);
}
