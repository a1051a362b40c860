#version 460
// ReGIR: fills each entry of every marked cell with one light by resampled importance sampling:
// `candidates` emitters drawn by power (alias table), target = regirTarget (power over the squared
// box distance, zero for lights turned away from the cell), and stores the chosen slot with its
// contribution weight W = sum(w) / (candidates x target(chosen)). A consumer that draws an entry
// uniformly treats W as 1 / (its probability), so its own RIS stays unbiased (RIS inside RIS).
#extension GL_GOOGLE_include_directive : require

#include "regir/regir.glsl"

layout(local_size_x = REGIR_GROUP_SIZE) in;

layout(set = 0, binding = REGIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = REGIR_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = REGIR_BINDING_MARKS, std430) readonly buffer Marks { uint gMarks[]; };
layout(set = 0, binding = REGIR_BINDING_GRID, std430) buffer Grid {
    RegirGridInfo gGrid;
    RegirEntry gEntries[];
};

void main() {
    uint id = gl_GlobalInvocationID.x;
    uint cell = id / REGIR_CELL_ENTRIES;
    if (cell >= gGrid.dims.w || gMarks[cell] == 0u) return;
    uvec3 dims = gGrid.dims.xyz;
    uvec3 c = uvec3(cell % dims.x, (cell / dims.x) % dims.y, cell / (dims.x * dims.y));
    float size = gGrid.origin.w;
    vec3 lo = gGrid.origin.xyz + vec3(c) * size;
    vec3 hi = lo + size;
    uint rng = rngInit(uvec2(id, 0u), gGrid.build.y, 23u, gGrid.build.z);
    uint candidates = gGrid.build.x;
    float wSum = 0.0;
    float chosenTarget = 0.0;
    uint chosen = RESERVOIR_EMPTY;
    for (uint i = 0u; i < candidates; ++i) {
        uint slot;
        if (!pickEmitter(rng, true, slot)) break;
        GpuEmitter e = loadEmitter(slot);
        float pdf = e.radiance.w / gLights.power.x;
        float target = regirTarget(e, lo, hi, size);
        float w = pdf > 0.0 ? target / pdf : 0.0;
        wSum += w;
        if (w > 0.0 && rngNext(rng) * wSum < w) {
            chosen = slot;
            chosenTarget = target;
        }
    }
    float weight = chosenTarget > 0.0 ? wSum / (float(candidates) * chosenTarget) : 0.0;
    gEntries[id] = RegirEntry(chosenTarget > 0.0 ? chosen : RESERVOIR_EMPTY, weight);
}
