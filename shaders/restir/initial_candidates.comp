#version 460
// ReSTIR initial candidates (thesis §4.4-4.5, Bitterli et al. 2020 Alg. 3): M light samples per
// pixel, drawn uniformly or by power, resampled by weighted reservoir sampling with the
// unshadowed contribution's luminance as target pdf; optionally the chosen one is shadow-tested.
// The weight W stays the unshadowed one (spatial neighbours reuse it as is); the shadow test's
// answer goes to weights.w, which only this pixel's own reuse applies. With light tiles (by power),
// the candidates are consecutive entries of one random presampled tile: the same probabilities,
// read in order instead of drawn from the alias table. With ReGIR (sampling regir), each candidate
// is a uniformly drawn entry of the world-space cell the surface lies in, weighted by the entry's
// contribution weight in place of 1 / probability (RIS inside RIS; regir/regir.glsl).
#extension GL_GOOGLE_include_directive : require

#include "light_tiles/light_tiles.glsl"
#include "regir/regir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = FEATURE_CANDIDATE_VISIBILITY) const bool kCandidateVisibility = true;

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;  // loadGBuffer
layout(set = 0, binding = RESTIR_INITIAL_BINDING_OUT, std430) writeonly buffer Out { Reservoir gOut[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    Surface s = surfaceFrom(loadGBuffer(gGBuffer, index));
    Reservoir r = Reservoir(uvec4(RESERVOIR_EMPTY, 0u, 0u, 0u), vec4(0.0));
    uint candidates = gRestir.knobs.candidates;
    if (!s.valid || gLights.counts.x == 0u || candidates == 0u) {
        gOut[index] = r;
        return;
    }
    bool area = !kPointLights || gRestir.area != 0u;
    bool byPower = gRestir.byPower != 0u;
    uint rng = rngInit(pixel, gRestir.frameIndex, 1u, gRestir.seed);
    bool tiles = byPower && gRestir.knobs.lightTiles != 0u && lightTilesReady(gFrame);
    uint run = tiles ? lightTileRunStart(rng) : 0u;
    // ReGIR: the first entry of the surface's cell (a surface outside the grid draws by power).
    bool regir = regirReady(gFrame);
    // The header member by member from a pointer set up front: one struct load through a pointer
    // assigned in a branch read values that put every pixel outside the grid on lavapipe.
    RegirGridBuffer grid = regirGrid(gFrame);  // dereferenced only when regir
    uint cellEntries = 0u;
    if (regir) {
        RegirGridInfo info = RegirGridInfo(grid.info.origin, grid.info.dims, grid.info.build);
        uint cell = regirSurfaceCell(info, s);
        regir = cell < info.dims.w;
        cellEntries = cell * REGIR_CELL_ENTRIES;
    }

    float wSum = 0.0;
    float chosenTarget = 0.0;
    for (uint i = 0u; i < candidates; ++i) {
        uint slot;
        GpuEmitter e;
        float pdf;
        if (regir) {
            RegirEntry entry = grid.entries[cellEntries + min(uint(rngNext(rng) * float(REGIR_CELL_ENTRIES)), REGIR_CELL_ENTRIES - 1u)];
            if (entry.slot == RESERVOIR_EMPTY) continue;  // no light reaches this cell: a zero-weight candidate
            slot = entry.slot;
            e = loadEmitter(slot);
            pdf = 1.0 / entry.weight;
        } else if (tiles) {
            LightTileSample t = lightTileSample(gFrame, lightTileRunEntry(run, i));
            slot = t.info.z;
            e = lightTileEmitter(t);
            pdf = t.radiance.w;
        } else {
            pickEmitter(rng, byPower, slot);
            e = loadEmitter(slot);
            pdf = emitterPdf(slot, byPower);
        }
        uint face = LIGHT_FACE_CENTRE;
        vec2 uv = vec2(0.5);
        if (area) {
            float side = float(e.minCorner.w);
            pdf *= pickFace(e, s.position, rngNext(rng), face) / (side * side);
            // The reservoir stores uv in 16 bits; evaluate the point it will be able to recall.
            uv = unpackUnorm2x16(packUnorm2x16(vec2(rngNext(rng), rngNext(rng))));
        }
        float chooser = rngNext(rng);
        if (!(pdf > 0.0)) continue;
        vec3 toLight;
        float dist;
        float target = luminance(lightContribution(s, e, face, uv, toLight, dist));
        float w = target / pdf;
        wSum += w;
        if (w > 0.0 && chooser * wSum < w) {
            r.light = uvec4(slot, e.info.y, face, packUnorm2x16(uv));
            chosenTarget = target;
        }
    }
    r.weights = vec4(chosenTarget > 0.0 ? wSum / (float(candidates) * chosenTarget) : 0.0, float(candidates),
                     chosenTarget, 1.0);
    if (kCandidateVisibility && gRestir.knobs.candidateVisibility != 0u && r.light.x != RESERVOIR_EMPTY) {
        GpuEmitter e = loadEmitter(r.light.x);
        vec3 toLight;
        float dist;
        lightContribution(s, e, r.light.z, unpackUnorm2x16(r.light.w), toLight, dist);
        if (!lightVisible(s, e, toLight, dist)) r.weights.w = 0.0;
    }
    gOut[index] = r;
}
