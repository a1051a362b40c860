#version 460
// ReSTIR temporal reuse (thesis §4.4 and §4.9): merge this pixel's candidate reservoir with last
// frame's final reservoir at the motion-vector pixel, if that pixel saw the same surface (depth
// within the tolerance, same face normal); last frame's M is capped at `cap` x this frame's.
#extension GL_GOOGLE_include_directive : require

#include "common/reservoir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 0, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 1, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 2, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 3, std430) readonly buffer PrevGBuffer { GBufferTexel gPrevGBuffer[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 4, std430) buffer Current { Reservoir gCurrent[]; };
layout(set = 0, binding = LIT_PASS_BINDING_FIRST + 5, std430) readonly buffer Previous { Reservoir gPrevious[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = gGBuffer[index];
    Surface s = surfaceFrom(g);
    if (!s.valid || g.motion.w == 0.0) return;

    ivec2 prevPixel = ivec2(floor(g.motion.xy));
    if (any(lessThan(prevPixel, ivec2(0))) || any(greaterThanEqual(prevPixel, ivec2(gFrame.imageSize.xy)))) return;
    uint prevIndex = uint(prevPixel.x) + uint(prevPixel.y) * gFrame.imageSize.x;
    GBufferTexel pg = gPrevGBuffer[prevIndex];
    float tolerance = gRestir.reuse.z;
    if (uint(pg.voxel.w) != s.face || abs(gbufferDistance(pg) - g.motion.z) > tolerance * g.motion.z) return;

    Reservoir current = gCurrent[index];
    Reservoir previous = gPrevious[prevIndex];
    if (reservoirStale(previous)) return;  // its light is gone: drop it
    previous.weights.y = min(previous.weights.y, gRestir.reuse.y * float(gRestir.config.x));

    uint rng = rngInit(pixel, gRestir.config.w, 2u, gRestir.seeds.x);
    Combiner c = combinerStart();
    float targetCurrent = reservoirHasLight(current) ? current.weights.z : 0.0;
    combinerAdd(c, current, targetCurrent, rngNext(rng));
    combinerAdd(c, previous, targetAt(s, previous), rngNext(rng));

    float normaliser = c.M;
    if ((gRestir.config.y & RESTIR_UNBIASED) != 0u) {
        // Count only the inputs whose pixel could have produced the chosen sample: its target
        // there is positive and, for the other pixel, the sample is visible from it.
        Surface prevSurface = surfaceFrom(pg);
        // This pixel always could (the chosen sample has a positive target here).
        normaliser = current.weights.y;
        if (reservoirHasLight(c.chosen) && targetAt(prevSurface, c.chosen) > 0.0 && visibleAt(prevSurface, c.chosen))
            normaliser += previous.weights.y;
    }
    gCurrent[index] = combinerFinish(c, normaliser);
}
