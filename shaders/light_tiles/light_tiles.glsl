// Reading the frame's presampled light tiles (shared/light_tiles.h), reached through the device
// address in FrameParams::lightTiles so that any pass with the frame parameters can read them
// without a binding of its own. Every entry was drawn by power, as pickEmitter draws, so an entry
// (or a run of consecutive entries of one tile) stands in for alias-table draws with the same
// probabilities.
#ifndef LIGHT_TILES_LIGHT_TILES_GLSL
#define LIGHT_TILES_LIGHT_TILES_GLSL

#extension GL_EXT_buffer_reference : require

#include "common/direct_light.glsl"
#include "shared/light_tiles.h"
#include "shared/shader_features.h"

layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer LightTileBuffer {
    LightTileSample samples[];
};

layout(constant_id = FEATURE_LIGHT_TILES) const bool kLightTilesFeature = true;

// Did this frame draw tiles? (Only the frames whose lighting reads them do; compiled out for the
// others.)
bool lightTilesReady(FrameParams f) { return kLightTilesFeature && (f.lightTiles.x | f.lightTiles.y) != 0u; }

LightTileSample lightTileSample(FrameParams f, uint entry) {
    LightTileBuffer tiles = LightTileBuffer(uint64_t(f.lightTiles.x) | (uint64_t(f.lightTiles.y) << 32));
    return tiles.samples[entry];
}

// The start of a run of entries: a random tile and a random place in it.
uint lightTileRunStart(inout uint rng) {
    uint tile = min(uint(rngNext(rng) * float(LIGHT_TILE_COUNT)), LIGHT_TILE_COUNT - 1u);
    uint offset = min(uint(rngNext(rng) * float(LIGHT_TILE_SIZE)), LIGHT_TILE_SIZE - 1u);
    return tile * LIGHT_TILE_SIZE + offset;
}

// Entry i of the run, wrapping around within its tile.
uint lightTileRunEntry(uint start, uint i) {
    uint base = start - start % LIGHT_TILE_SIZE;
    return base + (start + i) % LIGHT_TILE_SIZE;
}

// The entry's emitter as the light-sampling maths takes it (radiance.w holds the probability).
GpuEmitter lightTileEmitter(LightTileSample t) {
    return GpuEmitter(t.minCorner, t.radiance, uvec4(t.info.x, t.info.y, 0u, EMITTER_FLAG_ALIVE));
}

// One emitter sample for `s`, unshadowed (sampleEmitter): the emitter drawn from a random tile
// entry when the frame drew tiles, else by power from the alias table; `value` is its
// contribution over its density, (toLight, dist) its shadow ray. False when there is no light or
// it cannot reach the surface.
bool emitterSampleUnshadowed(Surface s, FrameParams frame, inout uint rng, out GpuEmitter e, out vec3 value,
                             out vec3 toLight, out float dist) {
    value = vec3(0.0);
    toLight = vec3(0.0, 0.0, 1.0);
    dist = 0.0;
    float chosen;
    if (lightTilesReady(frame)) {
        LightTileSample t = lightTileSample(frame, lightTileRunStart(rng));
        e = lightTileEmitter(t);
        chosen = t.radiance.w;
        if (!(chosen > 0.0)) return false;  // no lights this frame
    } else {
        uint slot;
        if (!pickEmitter(rng, true, slot)) return false;
        e = loadEmitter(slot);
        chosen = emitterPdf(slot, true);
    }
    vec3 f;
    float pdf;
    uint face;
    if (!sampleEmitter(s, e, chosen, rng, f, pdf, face, toLight, dist)) return false;
    value = f / pdf;
    return true;
}

// The direct light at `s` with one shadow ray instead of two: the sun's unshadowed light and one
// emitter sample's are both computed, one of them is picked with probability proportional to its
// size and its shadow ray traced, and the survivor is divided by that probability. Unbiased (each
// term's expectation is kept), and where neither is shadowed it returns their exact sum; the
// variance it adds comes only from shadows. One traversal for every lane: the branch picks the
// ray, not the trace (lavapipe would run both traces where lanes disagree).
vec3 directLightOneShadowRay(Surface s, FrameParams frame, inout uint rng) {
    vec3 sun = sunUnshadowed(s, frame);
    GpuEmitter e;
    vec3 emitted, toLight;
    float dist;
    if (!emitterSampleUnshadowed(s, frame, rng, e, emitted, toLight, dist)) emitted = vec3(0.0);
    float ws = sun.r + sun.g + sun.b, we = emitted.r + emitted.g + emitted.b;
    if (!(ws + we > 0.0)) return vec3(0.0);
    float pSun = ws / (ws + we);
    bool toSun = rngNext(rng) < pSun;
    SceneHit hit = traceScene(s.position + s.normal * kRayOffset, toSun ? frame.sunDirection.xyz : toLight,
                              toSun ? 1.0e30 : dist + kRayOffset);
    if (toSun) return hit.hit ? vec3(0.0) : sun / pSun;
    return shadowHitReachesEmitter(hit, e) ? emitted / (1.0 - pSun) : vec3(0.0);
}

#endif
