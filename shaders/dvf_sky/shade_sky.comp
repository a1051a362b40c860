#version 460
// DVF sky light: per pixel, the mask of the (cell, face) on the open side of the G-buffer's face
// times the face's precomputed weights (sky gradient x cos / pi, integrated over each direction
// texel), times albedo and sky radiance, added to the frame's radiance and written alone. A
// (cell, face) without a slot on this face's side (one short ray to the slot's anchor) takes one
// and queues it; until the mask is traced every face that finds the slot joins the choice of its
// anchor (the largest dvfAnchorRank wins, whatever the thread order). Masks exist only where the
// camera looks; until its mask is traced a slot adds nothing.
#extension GL_GOOGLE_include_directive : require

#include "dvf_sky/dvf_sky.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// Slots of one key, at most: a cell that a wall or floor crosses has faces of one orientation on
// both sides of it (a floor inside and the ground outside), which must not share a mask.
const uint kSlotsPerKey = 4u;

// Whether the open-side voxels `a` and `b` of two faces see each other: then they are on the same
// side of whatever crosses their cell, and may share a mask.
bool sameSide(ivec3 a, ivec3 b) {
    if (a == b) return true;
    vec3 from = vec3(a) + 0.5, to = vec3(b) + 0.5;
    float dist = length(to - from);
    return !traceScene(from, (to - from) / dist, dist).hit;
}

// A face of a slot whose mask is not traced yet: its open voxel may become the anchor.
uint joinSlot(uint s, ivec3 open) {
    atomicMax(gSlots[s].anchorRank, dvfAnchorRank(open));
    return s;
}

// The slot of `key` whose anchor is on this face's side, inserting one (anchored at `open`) if
// there is none; DVF_CAPACITY when the table is too full or the probe sequence ran out.
uint findOrInsert(uint key, ivec3 open) {
    uint h = dvfHome(key);
    uint fallback = DVF_CAPACITY, matches = 0u;
    for (uint i = 0u; i < DVF_MAX_PROBES; ++i) {
        uint s = (h + i) & (DVF_CAPACITY - 1u);
        uint k = gSlots[s].key;
        if (k == key) {
            // Not traced yet: this face joins the choice of the anchor (its mask is not read yet).
            if ((gSlots[s].state & DVF_STATE_VALID) == 0u) return joinSlot(s, open);
            if (sameSide(open, dvfAnchor(gSlots[s].anchor.xyz, gSlots[s].anchorRank))) return s;
            if (fallback == DVF_CAPACITY) fallback = s;
            if (++matches == kSlotsPerKey) return fallback;
            continue;
        }
        if (k != DVF_EMPTY_KEY) continue;
        // Keep a quarter free, so probe sequences stay short; the host clears a full table.
        if (gHeader.used >= DVF_CAPACITY - DVF_CAPACITY / 4u) return fallback;
        uint prev = atomicCompSwap(gSlots[s].key, DVF_EMPTY_KEY, key);
        if (prev == DVF_EMPTY_KEY) {
            // A zeroed slot: state 0 (not valid), so a pixel that finds it before its mask is
            // traced adds nothing.
            gSlots[s].anchor = ivec4(dvfCellOf(open) * int(1u << DVF_CELL_SHIFT), 0);
            atomicMax(gSlots[s].anchorRank, dvfAnchorRank(open));
            gSlots[s].maskDirty = uvec4(0u, 0u, 0xFFFFFFFFu, 0xFFFFFFFFu);
            atomicOr(gSlots[s].state, DVF_STATE_QUEUED);
            atomicAdd(gHeader.used, 1u);
            uint at = atomicAdd(gHeader.tail, 1u);
            gQueue[at & (DVF_CAPACITY - 1u)] = s;
            return s;
        }
        if (prev == key) return joinSlot(s, open);  // another pixel of this (cell, face) took it just now
    }
    return fallback;
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    GBufferTexel g = gGBuffer[index];
    Surface s = surfaceFrom(g);
    vec3 term = vec3(0.0);
    if (s.valid) {
        ivec3 open = g.voxel.xyz + faceNormal(s.face);
        uint key = dvfKey(dvfCellOf(open), s.face);
        uint slot = findOrInsert(key, open);
        if (slot < DVF_CAPACITY && (gSlots[slot].state & DVF_STATE_VALID) != 0u) {
            uvec2 mask = gSlots[slot].maskDirty.xy;
            float sum = 0.0;
            for (uint d = 0u; d < DVF_DIRECTIONS; ++d) {
                if (dvfMaskBit(mask, d)) sum += gWeights[s.face * DVF_DIRECTIONS + d];
            }
            term = s.albedo * gFrame.skyRadiance.rgb * sum;
        }
    }
    gSky[index] = vec4(term, 1.0);
    gRadiance[index] += vec4(term, 0.0);
}
