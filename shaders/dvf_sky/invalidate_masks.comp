#version 460
// DVF: marks the directions an edit can have changed. For every slot, the directions whose
// texel, seen from anywhere in the slot's cell, can pass through an edited region's bounding sphere
// become dirty and the slot joins the trace queue; only those directions are traced again (the
// paper's point: trace only what can have changed). Runs only in frames with edits, before
// take_batch, so the edit's directions are traced in the same frame.
#extension GL_GOOGLE_include_directive : require

#include "dvf_sky/dvf_sky.glsl"

layout(local_size_x = 64) in;

// Largest angle between a texel's centre direction and any direction in it (radians); a texel of
// the 8x8 hemi-octahedral map spans at most ~0.303 rad from its centre (DvfDirections.TexelsSpanLessThanTheInvalidationMargin).
const float kTexelRadius = 0.32;

void main() {
    uint s = gl_GlobalInvocationID.x;
    if (s >= DVF_CAPACITY) return;
    uint key = gSlots[s].key;
    if (key == DVF_EMPTY_KEY) return;
    uint face = dvfKeyFace(key);
    vec3 n = vec3(faceNormal(face));
    // Rays start anywhere on the cell's faces (build_masks.comp): from its centre, widened by
    // its half diagonal.
    const float halfDiagonal = 0.5 * sqrt(3.0) * float(1u << DVF_CELL_SHIFT);
    vec3 origin = (vec3(dvfCellOf(gSlots[s].anchor.xyz)) + 0.5) * float(1u << DVF_CELL_SHIFT);
    uvec2 dirty = uvec2(0u);
    for (uint e = 0u; e < gDvf.editCount; ++e) {
        vec4 sphere = gDvf.edits[e];
        vec3 v = sphere.xyz - origin;
        float dist = length(v);
        float reach = sphere.w + halfDiagonal;
        if (dist <= reach) {
            dirty = uvec2(0xFFFFFFFFu);
            break;
        }
        if (dot(v, n) < -reach) continue;  // wholly behind the face
        float cone = asin(reach / dist) + kTexelRadius;
        vec3 axis = v / dist;
        for (uint d = 0u; d < DVF_DIRECTIONS; ++d) {
            vec2 uv = (vec2(d % DVF_GRID, d / DVF_GRID) + 0.5) / float(DVF_GRID);
            if (acos(clamp(dot(dvfDirection(face, uv), axis), -1.0, 1.0)) <= cone) {
                if (d < 32u) dirty.x |= 1u << d;
                else dirty.y |= 1u << (d - 32u);
            }
        }
    }
    if (dirty == uvec2(0u)) return;
    atomicOr(gSlots[s].maskDirty.z, dirty.x);
    atomicOr(gSlots[s].maskDirty.w, dirty.y);
    if ((atomicOr(gSlots[s].state, DVF_STATE_QUEUED) & DVF_STATE_QUEUED) == 0u) {
        uint at = atomicAdd(gHeader.tail, 1u);
        gQueue[at & (DVF_CAPACITY - 1u)] = s;
    }
}
