// Presampled light tiles (Wyman & Panteleev, "Rearchitecting spatiotemporal resampling for
// production", HPG 2021; NVIDIA RTXDI's "presampled light sets"): once per frame, a small pass
// draws LIGHT_TILE_COUNT tiles of LIGHT_TILE_SIZE emitters by power (the alias table) and copies
// each one's data beside its probability. Consumers read consecutive entries of one randomly
// chosen tile instead of drawing from the alias table: every entry is still drawn with the
// power-proportional probability, so estimators stay unbiased, but the reads are sequential and
// the alias table and emitter list are not touched. Packed on the host by
// engine/render/light_tiles/light_tiles.h.
#ifndef SHARED_LIGHT_TILES_H
#define SHARED_LIGHT_TILES_H
#include "bindings.h"
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint LIGHT_TILE_COUNT = 64u;
SHARED_CONST uint LIGHT_TILE_SIZE = 512u;
SHARED_CONST uint LIGHT_TILES_GROUP_SIZE = 64u;

// One presampled light: the emitter as GpuEmitter has it, with the probability of having drawn
// it in place of its power and its slot in place of its material.
struct LightTileSample {
    ivec4 minCorner;  // as GpuEmitter::minCorner
    vec4 radiance;    // rgb: as GpuEmitter::radiance; w: probability of drawing this emitter (power / total)
    uvec4 info;       // x: exposed-face mask, y: generation, z: emitter slot, w: unused
};
SHARED_ASSERT_SIZE(LightTileSample, 48);

struct LightTilesParams {
    uint frameIndex;
    uint seed;
    uint pad0, pad1;
};
SHARED_ASSERT_SIZE(LightTilesParams, 16);

// Own bindings of light_tiles/presample.comp, after the emitter list.
SHARED_CONST uint LIGHT_TILES_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 0u;   // LightTilesParams
SHARED_CONST uint LIGHT_TILES_BINDING_SAMPLES = LIT_PASS_BINDING_FIRST + 1u;  // LightTileSample per entry, written

SHARED_END

#endif
