// The emitter a static voxel belongs to, derived from the grid exactly as
// engine/lighting/emitter_list.cpp builds the CPU list: with brick lights on, a homogeneous
// emissive cell is one 8^3 light whose side is exposed when any voxel across it is empty;
// otherwise each emissive voxel is a light with its own exposed faces. Power = luminance x
// exposed faces x side^2 x pi, as in EmitterList::writeSlot. The GPU has no voxel -> slot map;
// the light-sampling pdf needs only the emitter's shape and power, so this recomputes them where
// a bounce ray lands on an emitter (rare, so the cell scan costs little).
#ifndef COMMON_EMITTER_LOOKUP_GLSL
#define COMMON_EMITTER_LOOKUP_GLSL

#include "common/emitters.glsl"

struct EmitterShape {
    GpuEmitter emitter;  // minCorner (xyz, w = side) and info.x (exposed faces) as the CPU list has them
    float power;
};

uint voxelExposureMask(ivec3 v) {
    uint mask = 0u;
    for (uint f = 0u; f < 6u; ++f) {
        if (gridVoxelMaterial(false, v + faceNormal(f)) == 0u) mask |= 1u << f;
    }
    return mask;
}

// A side of the cell is exposed when any of the 8 x 8 voxels across it is empty (or outside).
uint cellExposureMask(ivec3 cell) {
    uint mask = 0u;
    ivec3 lo = cell * 8;
    for (uint f = 0u; f < 6u; ++f) {
        uint axis = f >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
        ivec3 p = lo;
        p[axis] = (f & 1u) != 0u ? lo[axis] + 8 : lo[axis] - 1;
        bool exposed = false;
        for (int i = 0; i < 8 && !exposed; ++i) {
            for (int j = 0; j < 8 && !exposed; ++j) {
                ivec3 q = p;
                q[ua] += i;
                q[va] += j;
                exposed = gridVoxelMaterial(false, q) == 0u;
            }
        }
        if (exposed) mask |= 1u << f;
    }
    return mask;
}

// False when the static voxel is not part of any light of the list.
bool emitterOfStaticVoxel(ivec3 v, bool brickLights, out EmitterShape shape) {
    shape.emitter = GpuEmitter(ivec4(0), vec4(0.0), uvec4(0u));
    shape.power = 0.0;
    uint material = gridVoxelMaterial(false, v);
    if (material == 0u) return false;
    vec3 le = materialEmission(material);
    if (!any(greaterThan(le, vec3(0.0)))) return false;
    uint cell = gridCell(false, v >> 3);
    int side = 1;
    ivec3 lo = v;
    uint mask;
    if (brickLights && (cell & CELL_HOMOGENEOUS) != 0u) {
        side = 8;
        lo = (v >> 3) * 8;
        mask = cellExposureMask(v >> 3);
    } else {
        mask = voxelExposureMask(v);
    }
    if (mask == 0u) return false;
    shape.emitter = GpuEmitter(ivec4(lo, side), vec4(le, 0.0), uvec4(mask, 0u, material, EMITTER_FLAG_ALIVE));
    shape.power = luminance(le) * float(bitCount(mask)) * float(side * side) * PI;
    shape.emitter.radiance.w = shape.power;
    return true;
}

// Solid-angle density with which directLight's emitter sampling (by power, face by solid
// angle, uniform point on the face) produces the point at distance `dist` along a unit ray from
// x that enters face `face` of this emitter.
float lightSamplePdfSolidAngle(EmitterShape shape, uint face, vec3 x, float dist, vec3 dir) {
    float cosLight = dot(faceNormalF(face), -dir);
    if (!(cosLight > 0.0) || !(gLights.power.x > 0.0)) return 0.0;
    float side = float(shape.emitter.minCorner.w);
    float areaPdf = shape.power / gLights.power.x * facePdf(shape.emitter, x, face) / (side * side);
    return areaPdf * dist * dist / cosLight;
}

#endif
