// ReGIR's grid (shared/regir.h) as its passes and its consumers read it. The consumers (ReSTIR's
// and RIS's candidates) find the grid through the device address in FrameParams::regirGrid, so
// they need no binding of their own; the passes that fill it bind it.
#ifndef REGIR_REGIR_GLSL
#define REGIR_REGIR_GLSL

#extension GL_EXT_buffer_reference : require

#include "common/surface.glsl"
#include "shared/regir.h"
#include "shared/shader_features.h"

layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer RegirGridBuffer {
    RegirGridInfo info;
    RegirEntry entries[];
};

layout(constant_id = FEATURE_REGIR) const bool kRegirFeature = true;

// Did this frame fill the grid? (Only the frames whose candidates read it do; compiled out for
// the others.)
bool regirReady(FrameParams f) { return kRegirFeature && (f.regirGrid.x | f.regirGrid.y) != 0u; }

RegirGridBuffer regirGrid(FrameParams f) {
    return RegirGridBuffer(uint64_t(f.regirGrid.x) | (uint64_t(f.regirGrid.y) << 32));
}

// The cell a surface looks up: half a voxel off the surface along its normal, so a surface on a
// cell boundary belongs to the cell on its lit side. The mark pass and the consumers agree on it.
uint regirSurfaceCell(RegirGridInfo g, Surface s) { return regirCellOf(g, s.position + 0.5 * s.normal); }

// The build's target for emitter e at the cell [lo, hi]: its power over the squared distance
// between the two boxes, no less than a cell's size squared (a conservative bound of what the
// light can give a point of the cell), and 0 when none of its exposed faces is turned towards any
// point of the cell. The face test uses the emitter's far side as the plane a lit point must lie
// beyond (point mode's light sits inside the box), so it never excludes a light that can reach
// the cell: every light with power keeps a positive target wherever it can contribute.
float regirTarget(GpuEmitter e, vec3 lo, vec3 hi, float cellSize) {
    vec3 elo = vec3(e.minCorner.xyz);
    vec3 ehi = elo + float(e.minCorner.w);
    uint faces = e.info.x;
    // Bit 2a: face -a (lights points below ehi[a]); bit 2a+1: face +a (points above elo[a]).
    uvec3 minus = (uvec3(faces) >> uvec3(0u, 2u, 4u)) & 1u;
    uvec3 plus = (uvec3(faces) >> uvec3(1u, 3u, 5u)) & 1u;
    bvec3 facing = bvec3((minus & uvec3(lessThan(lo, ehi))) | (plus & uvec3(greaterThan(hi, elo))));
    if (!any(facing)) return 0.0;
    vec3 gap = max(max(elo - hi, lo - ehi), vec3(0.0));
    return e.radiance.w / max(dot(gap, gap), cellSize * cellSize);
}

#endif
