#version 460
// Presampled light tiles: each thread draws one emitter by power from the alias table and copies
// its data and probability into its tile entry, so this frame's consumers read tiles in order
// instead of drawing from the alias table per sample.
#extension GL_GOOGLE_include_directive : require

#include "common/emitters.glsl"
#include "shared/light_tiles.h"

layout(local_size_x = LIGHT_TILES_GROUP_SIZE) in;

layout(set = 0, binding = LIGHT_TILES_BINDING_PARAMS, std430) readonly buffer Params { LightTilesParams gParams; };
layout(set = 0, binding = LIGHT_TILES_BINDING_SAMPLES, std430) writeonly buffer Samples { LightTileSample gSamples[]; };

void main() {
    uint entry = gl_GlobalInvocationID.x;
    if (entry >= LIGHT_TILE_COUNT * LIGHT_TILE_SIZE) return;
    uint rng = rngInit(uvec2(entry, 0u), gParams.frameIndex, 21u, gParams.seed);
    LightTileSample t = LightTileSample(ivec4(0), vec4(0.0), uvec4(0u, 0u, RESERVOIR_EMPTY, 0u));
    uint slot;
    if (pickEmitter(rng, true, slot)) {
        GpuEmitter e = loadEmitter(slot);
        t = LightTileSample(e.minCorner, vec4(e.radiance.rgb, emitterPdf(slot, true)), uvec4(e.info.x, e.info.y, slot, 0u));
    }
    gSamples[entry] = t;
}
