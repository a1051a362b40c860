#version 460
// ReSTIR initial candidates (thesis §4.4-4.5, Bitterli et al. 2020 Alg. 3): M light samples per
// pixel, drawn uniformly or by power, resampled by weighted reservoir sampling with the
// unshadowed contribution's luminance as target pdf; optionally the chosen one is shadow-tested.
// The weight W stays the unshadowed one (spatial neighbours reuse it as is); the shadow test's
// answer goes to weights.w, which only this pixel's own reuse applies.
//
// Emitters drawn uniformly, by power or from light tiles are shared across the subgroup: in each
// round every lane draws one emitter and loads it, and every lane then evaluates all of the
// round's emitters at its own surface, with its own face and point on each. A pixel's M
// candidates are still M independent draws with the sampler's probabilities (the estimators are
// unchanged); a lane fetches one emitter per round instead of one per candidate, which on
// lavapipe (8 lanes) is a quarter of the pass. Neighbouring pixels of a subgroup see the same
// emitters in a frame, each at its own point. With light tiles (by power), a lane's draws are
// consecutive entries of one random presampled tile: the same probabilities, read in order
// instead of drawn from the alias table. With ReGIR (sampling regir), each candidate is a
// uniformly drawn entry of the world-space cell the surface lies in, weighted by the entry's
// contribution weight in place of 1 / probability (RIS inside RIS; regir/regir.glsl): those
// depend on the pixel's cell, so each pixel draws its own.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_shuffle : require
#extension GL_KHR_shader_subgroup_vote : require

#include "light_tiles/light_tiles.glsl"
#include "regir/regir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = FEATURE_CANDIDATE_VISIBILITY) const bool kCandidateVisibility = true;

layout(set = 0, binding = RESTIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = RESTIR_BINDING_PARAMS, std430) readonly buffer Restir { RestirParams gRestir; };
layout(set = 0, binding = RESTIR_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;  // loadGBuffer
layout(set = 0, binding = RESTIR_INITIAL_BINDING_OUT, std430) writeonly buffer Out { Reservoir gOut[]; };

// The pixel's reservoir under construction (weighted reservoir sampling).
struct Stream {
    Reservoir r;
    float wSum;
    float chosenTarget;
};

// Adds one candidate: emitter e in `slot`, drawn with probability `pdf`; area mode picks the face
// and point here, with the pixel's own random numbers.
void addCandidate(inout Stream st, Surface s, bool area, uint slot, GpuEmitter e, float pdf, inout uint rng) {
    uint face = LIGHT_FACE_CENTRE;
    vec2 uv = vec2(0.5);
    if (area) {
        float side = float(e.minCorner.w);
        pdf *= pickFace(e, s.position, rngNext(rng), face) / (side * side);
        // The reservoir stores uv in 16 bits; evaluate the point it will be able to recall.
        uv = unpackUnorm2x16(packUnorm2x16(vec2(rngNext(rng), rngNext(rng))));
    }
    float chooser = rngNext(rng);
    if (!(pdf > 0.0)) return;
    vec3 toLight;
    float dist;
    float target = luminance(lightContribution(s, e, face, uv, toLight, dist));
    float w = target / pdf;
    st.wSum += w;
    if (w > 0.0 && chooser * st.wSum < w) {
        st.r.light = uvec4(slot, e.info.y, face, packUnorm2x16(uv));
        st.chosenTarget = target;
    }
}

// One emitter drawn without ReGIR: entry i of the pixel's light-tile run, else from the alias table
// (by power) or uniformly; its slot, the emitter and the probability it was drawn with.
void drawEmitter(bool byPower, bool tiles, uint run, uint i, inout uint rng, out uint slot, out GpuEmitter e,
                 out float pdf) {
    if (tiles) {
        LightTileSample t = lightTileSample(gFrame, lightTileRunEntry(run, i));
        slot = t.info.z;
        e = lightTileEmitter(t);
        pdf = t.radiance.w;
    } else {
        pickEmitter(rng, byPower, slot);
        e = loadEmitter(slot);
        pdf = emitterPdfOf(e, byPower);
    }
}

// ReGIR: every candidate from the surface's cell; a surface outside the grid draws by power.
void regirCandidates(inout Stream st, Surface s, bool area, bool byPower, bool tiles, uint candidates, inout uint rng) {
    uint run = tiles ? lightTileRunStart(rng) : 0u;
    // The header member by member from a pointer set up front: one struct load through a pointer
    // assigned in a branch read values that put every pixel outside the grid on lavapipe.
    RegirGridBuffer grid = regirGrid(gFrame);
    RegirGridInfo info = RegirGridInfo(grid.info.origin, grid.info.dims, grid.info.build);
    uint cell = regirSurfaceCell(info, s);
    bool inGrid = cell < info.dims.w;
    uint cellEntries = cell * REGIR_CELL_ENTRIES;
    for (uint i = 0u; i < candidates; ++i) {
        uint slot;
        GpuEmitter e;
        float pdf;
        if (inGrid) {
            RegirEntry entry = grid.entries[cellEntries + min(uint(rngNext(rng) * float(REGIR_CELL_ENTRIES)), REGIR_CELL_ENTRIES - 1u)];
            if (entry.slot == RESERVOIR_EMPTY) continue;  // no light reaches this cell: a zero-weight candidate
            slot = entry.slot;
            e = loadEmitter(slot);
            pdf = 1.0 / entry.weight;
        } else {
            drawEmitter(byPower, tiles, run, i, rng, slot, e, pdf);
        }
        addCandidate(st, s, area, slot, e, pdf, rng);
    }
}

// Uniform, by power or from light tiles: rounds of one draw per lane, shared by the subgroup.
// Every lane of the subgroup runs this (pixels off the image and sky pixels draw, but add
// nothing), so the shuffles read only lanes that took part.
void sharedCandidates(inout Stream st, Surface s, bool lit, bool area, bool byPower, bool tiles, uint candidates,
                      inout uint rng) {
    uint run = tiles ? lightTileRunStart(rng) : 0u;
    uint lanes = gl_SubgroupSize;
    // A subgroup of sky or off-image pixels skips the rounds: on lavapipe a loop no lane enters
    // costs nothing, where the masked candidate maths would run for every lane.
    bool any = subgroupAny(lit);
    for (uint round = 0u; any && round * lanes < candidates; ++round) {
        uint ownSlot;
        GpuEmitter own;
        float ownPdf;
        drawEmitter(byPower, tiles, run, round, rng, ownSlot, own, ownPdf);
        uint count = min(lanes, candidates - round * lanes);
        for (uint j = 0u; j < count; ++j) {
            uint slot = subgroupShuffle(ownSlot, j);
            GpuEmitter e = GpuEmitter(subgroupShuffle(own.minCorner, j), subgroupShuffle(own.radiance, j),
                                      subgroupShuffle(own.info, j));
            float pdf = subgroupShuffle(ownPdf, j);
            if (lit) addCandidate(st, s, area, slot, e, pdf, rng);
        }
    }
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    bool inImage = all(lessThan(pixel, gFrame.imageSize.xy));
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    Surface s;
    s.valid = false;
    if (inImage) s = surfaceFrom(loadGBuffer(gGBuffer, index));
    Stream st = Stream(Reservoir(uvec4(RESERVOIR_EMPTY, 0u, 0u, 0u), vec4(0.0)), 0.0, 0.0);
    uint candidates = gRestir.knobs.candidates;
    bool lit = inImage && s.valid;
    bool draws = gLights.counts.x != 0u && candidates != 0u;
    if (draws) {
        bool area = !kPointLights || gRestir.area != 0u;
        bool byPower = gRestir.byPower != 0u;
        bool tiles = byPower && gRestir.knobs.lightTiles != 0u && lightTilesReady(gFrame);
        uint rng = rngInit(pixel, gRestir.frameIndex, 1u, gRestir.seed);
        if (regirReady(gFrame)) {
            if (lit) regirCandidates(st, s, area, byPower, tiles, candidates, rng);
        } else {
            sharedCandidates(st, s, lit, area, byPower, tiles, candidates, rng);
        }
    }
    if (!inImage) return;
    Reservoir r = st.r;
    if (lit && draws) {
        r.weights = vec4(st.chosenTarget > 0.0 ? st.wSum / (float(candidates) * st.chosenTarget) : 0.0,
                         float(candidates), st.chosenTarget, 1.0);
    }
    if (kCandidateVisibility && gRestir.knobs.candidateVisibility != 0u && r.light.x != RESERVOIR_EMPTY) {
        GpuEmitter e = loadEmitter(r.light.x);
        vec3 toLight;
        float dist;
        lightContribution(s, e, r.light.z, unpackUnorm2x16(r.light.w), toLight, dist);
        if (!lightVisible(s, e, toLight, dist)) r.weights.w = 0.0;
    }
    gOut[index] = r;
}
