// Emitter list as the GPU sees it (engine/lighting/emitter_list.h keeps it up to date).
//
// Slots are stable: an emitter keeps its slot while it exists, and a slot's generation changes
// whenever it is freed or reused, so a reservoir holding (slot, generation) can tell that its
// light is gone. Uniform candidates index `alive` (the slots in use); power-proportional
// candidates use the alias table, whose entries are also slots.
#ifndef SHARED_EMITTERS_H
#define SHARED_EMITTERS_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint EMITTER_FLAG_ALIVE = 1u;

struct GpuEmitter {
    ivec4 minCorner;  // xyz: lowest voxel of the emitter; w: edge length in voxels (1 voxel, 8 brick light)
    vec4 radiance;    // rgb: emitted radiance of every exposed face; w: power (luminance x exposed area x pi)
    uvec4 info;       // x: exposed-face mask (bit f = face f, shared::FACE_*), y: generation,
                      // z: material id, w: EMITTER_FLAG_*
};
SHARED_ASSERT_SIZE(GpuEmitter, 48);

// Walker/Vose alias table entry over emitter slots.
struct AliasEntry {
    float probability;  // keep this slot with this probability, else take `alias`
    uint slot;
    uint alias;
    float pdf;  // probability of choosing `slot` overall: its power / total power
};
SHARED_ASSERT_SIZE(AliasEntry, 16);

struct EmitterListInfo {
    uvec4 counts;  // x: alive emitters, y: slots, z: alias table entries, w: unused
    vec4 power;    // x: total power, yzw unused
};
SHARED_ASSERT_SIZE(EmitterListInfo, 32);

SHARED_END

#endif
