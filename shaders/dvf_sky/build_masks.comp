#version 460
// DVF: traces this frame's batch of masks, one workgroup per slot and one thread per direction.
// Only the slot's dirty directions are traced. A bit is DVF_RAYS_PER_DIRECTION rays' answer,
// dithered: set with probability (weight of the rays that escaped) / (weight of all), each ray
// weighted by cos x solid angle at its point of the texel, through a jittered point
// of the direction's texel from a random point of the cell's faces of this orientation on the
// anchor's side (dvfOrigin). So a bit's expectation is the fraction of the texel the cell's faces
// see (by the texel's own weighting) — the mask's mean is unbiased, where a majority vote loses a
// small window's partial texels.
#extension GL_GOOGLE_include_directive : require

#include "dvf_sky/dvf_sky.glsl"

layout(local_size_x = 64) in;

// A random point on a face of this orientation in the slot's cell, at the anchor's level and on
// its side (a short ray from the anchor's open voxel reaches it); else a random point of the
// anchor face. Faces of other levels in the cell are not sampled: they share the mask as it is.
vec3 dvfOrigin(ivec3 anchor, uint face, inout uint rng) {
    vec3 n, t, b;
    dvfFaceFrame(face, n, t, b);
    ivec3 cellMin = dvfCellOf(anchor) * int(1u << DVF_CELL_SHIFT);
    uint axis = face >> 1u;
    ivec3 c = anchor;
    c[(axis + 1u) % 3u] = cellMin[(axis + 1u) % 3u] + int(rngNext(rng) * float(1u << DVF_CELL_SHIFT));
    c[(axis + 2u) % 3u] = cellMin[(axis + 2u) % 3u] + int(rngNext(rng) * float(1u << DVF_CELL_SHIFT));
    ivec3 solid = c - ivec3(n);
    bool onFace = all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, gWorld.sizeInVoxels.xyz)) &&
                  all(greaterThanEqual(solid, ivec3(0))) && all(lessThan(solid, gWorld.sizeInVoxels.xyz)) &&
                  staticVoxelMaterial(c) == 0u && staticVoxelMaterial(solid) != 0u;
    if (onFace && c != anchor) {
        vec3 from = vec3(anchor) + 0.5, to = vec3(c) + 0.5;
        float dist = length(to - from);
        onFace = !traceScene(from, (to - from) / dist, dist).hit;
    }
    ivec3 at = onFace ? c : anchor;
    vec3 faceCentre = vec3(at) + 0.5 - 0.5 * n;
    return faceCentre + (rngNext(rng) - 0.5) * t + (rngNext(rng) - 0.5) * b + n * kRayOffset;
}

void main() {
    uint item = gl_WorkGroupID.x;
    if (item >= gHeader.batchCount) return;  // the whole workgroup leaves together
    uint s = gQueue[(gHeader.batchStart + item) & (DVF_CAPACITY - 1u)];
    uint d = gl_LocalInvocationID.x;
    uint key = gSlots[s].key;
    uint face = dvfKeyFace(key);
    uvec2 dirty = gSlots[s].maskDirty.zw;
    if (dvfMaskBit(dirty, d)) {
        ivec3 anchor = dvfAnchor(gSlots[s].anchor.xyz, gSlots[s].anchorRank);
        // Seeded by what the mask is (key, anchor, direction), not by its slot or frame, which
        // depend on the order the GPU's threads ran in.
        uint rng = rngInit(uvec2(key, gSlots[s].anchorRank * 64u + d), 0u, 21u, gDvf.seed);
        vec3 n = vec3(faceNormal(face));
        float seen = 0.0, total = 0.0;
        for (uint r = 0u; r < DVF_RAYS_PER_DIRECTION; ++r) {
            // Stratified over the texel (2x2), each ray weighted by what it stands for in the
            // texel's weight: cos x solid angle per unit of uv (the map's Jacobian).
            vec2 sub = (vec2(r & 1u, (r >> 1u) & 1u) + vec2(rngNext(rng), rngNext(rng))) * 0.5;
            vec2 uv = (vec2(d % DVF_GRID, d / DVF_GRID) + sub) / float(DVF_GRID);
            vec3 dir = dvfDirection(face, uv);
            const float h = 1.0e-3;
            vec3 du = dvfDirection(face, uv + vec2(h, 0.0)) - dvfDirection(face, uv - vec2(h, 0.0));
            vec3 dv = dvfDirection(face, uv + vec2(0.0, h)) - dvfDirection(face, uv - vec2(0.0, h));
            float w = max(dot(dir, n), 0.0) * length(cross(du, dv)) + 1.0e-12;
            total += w;
            vec3 origin = dvfOrigin(anchor, face, rng);
            if (!traceScene(origin, dir, 1.0e30).hit) seen += w;
        }
        bool visible = seen > rngNext(rng) * total;
        uint bit = 1u << (d & 31u);
        if (d < 32u) {
            if (visible) atomicOr(gSlots[s].maskDirty.x, bit);
            else atomicAnd(gSlots[s].maskDirty.x, ~bit);
        } else {
            if (visible) atomicOr(gSlots[s].maskDirty.y, bit);
            else atomicAnd(gSlots[s].maskDirty.y, ~bit);
        }
        atomicAdd(gHeader.tracedRays, DVF_RAYS_PER_DIRECTION);
    }
    memoryBarrierBuffer();
    barrier();
    if (d == 0u) {
        gSlots[s].maskDirty.zw = uvec2(0u);
        atomicAnd(gSlots[s].state, ~DVF_STATE_QUEUED);
        atomicOr(gSlots[s].state, DVF_STATE_VALID);
    }
}
