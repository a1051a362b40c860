// The discrete visibility field's buffers and its few shared functions: the hemi-octahedral
// direction of a mask bit (engine/render/dvf_sky/dvf_directions.cpp is the same map on the
// host), the key of a (cell, face) and the hash-table lookup. Included by every dvf_sky shader.
#ifndef DVF_SKY_DVF_SKY_GLSL
#define DVF_SKY_DVF_SKY_GLSL

#include "common/surface.glsl"
#include "shared/dvf_sky.h"

layout(set = 0, binding = DVF_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = DVF_BINDING_PARAMS, std430) readonly buffer DvfParamsBuffer { DvfParams gDvf; };
layout(set = 0, binding = DVF_BINDING_HEADER, std430) buffer DvfHeaderBuffer { DvfHeader gHeader; };
layout(set = 0, binding = DVF_BINDING_SLOTS, std430) buffer DvfSlots { DvfSlot gSlots[]; };
layout(set = 0, binding = DVF_BINDING_QUEUE, std430) buffer DvfQueue { uint gQueue[]; };
layout(set = 0, binding = DVF_BINDING_WEIGHTS, std430) readonly buffer DvfWeights { float gWeights[]; };
layout(set = 0, binding = DVF_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = DVF_BINDING_RADIANCE, std430) buffer Radiance { vec4 gRadiance[]; };
layout(set = 0, binding = DVF_BINDING_SKY, std430) buffer SkyTerm { vec4 gSky[]; };

// The face's tangent frame: the two other axes in cyclic order.
void dvfFaceFrame(uint face, out vec3 n, out vec3 t, out vec3 b) {
    uint axis = face >> 1u;
    n = vec3(faceNormal(face));
    t = vec3(0.0);
    b = vec3(0.0);
    t[(axis + 1u) % 3u] = 1.0;
    b[(axis + 2u) % 3u] = 1.0;
}

// Direction through point `uv` (in [0,1]² of the whole grid) of the hemi-octahedral map about
// the face normal: the square turned 45° onto the diamond |x| + |y| <= 1, lifted to the hemisphere.
vec3 dvfDirection(uint face, vec2 uv) {
    vec2 p = uv * 2.0 - 1.0;
    float x = (p.x + p.y) * 0.5, y = (p.y - p.x) * 0.5;
    float z = 1.0 - abs(x) - abs(y);
    vec3 n, t, b;
    dvfFaceFrame(face, n, t, b);
    return normalize(x * t + y * b + z * n);
}

// The inverse: the texel (bit) of a direction in the face's hemisphere.
uint dvfTexel(uint face, vec3 dir) {
    vec3 n, t, b;
    dvfFaceFrame(face, n, t, b);
    vec3 l = vec3(dot(dir, t), dot(dir, b), max(dot(dir, n), 0.0));
    l /= abs(l.x) + abs(l.y) + l.z;
    vec2 p = vec2(l.x - l.y, l.x + l.y);  // inverse of the 45° turn
    uvec2 c = uvec2(clamp((p * 0.5 + 0.5) * float(DVF_GRID), vec2(0.0), vec2(float(DVF_GRID) - 0.5)));
    return c.x + c.y * DVF_GRID;
}

uint dvfKey(ivec3 cell, uint face) {
    return (uint(cell.x) | (uint(cell.y) << 10u) | (uint(cell.z) << 19u) | (face << 29u)) + 1u;
}

uint dvfKeyFace(uint key) { return (key - 1u) >> 29u; }

// The cell on a face's open side (clamped into the world: a face on the world's boundary uses
// the cell it is in).
ivec3 dvfCellOf(ivec3 openVoxel) {
    return clamp(openVoxel >> int(DVF_CELL_SHIFT), ivec3(0), gWorld.sizeInCells.xyz - 1);
}

// The anchor's place in its cell, one higher in each axis (an open voxel just outside the world
// sits in the clamped edge cell, one step out), packed 4 bits an axis in the low 12 bits, under a
// hash of it: the maximum over the asking pixels is a pseudo-random one of them (a fixed rule
// such as "the lowest voxel" favours corners, which see less sky), the same whatever order the
// threads ran in. Never 0, the value of a slot no pixel asked for yet.
uint dvfAnchorRank(ivec3 open) {
    ivec3 l = clamp(open - dvfCellOf(open) * int(1u << DVF_CELL_SHIFT) + 1, ivec3(0), ivec3(15));
    uint packed = uint(l.x | (l.y << 4) | (l.z << 8));
    return (pcgHash(packed + 0x9E3779B9u) & 0xFFFFF000u) | packed | 0x1000u * uint(packed == 0u);
}
ivec3 dvfAnchor(ivec3 cellMin, uint rank) {
    uint p = rank & 0xFFFu;
    return cellMin + ivec3(int(p & 15u), int((p >> 4u) & 15u), int(p >> 8u)) - 1;
}

uint dvfHome(uint key) { return pcgHash(key) & (DVF_CAPACITY - 1u); }

bool dvfMaskBit(uvec2 mask, uint d) { return ((d < 32u ? mask.x : mask.y) >> (d & 31u) & 1u) != 0u; }

#endif
