// The voxel-face irradiance cache as the GPU sees it (engine/lighting/irradiance_cache.h keeps
// the CPU side). Entries are (voxel, set) pairs in slots; a hash table maps keys to slots.
//
// Per slot: CacheEntry; CACHE_FACES * K packed static hits (the static set's cached rays);
// CACHE_FACES irradiance values, accumulated and filtered. Per entry in this frame's update list
// and per traced ray: the selected hit (static or dynamic, bit CACHE_HIT_DYNAMIC).
//
// A packed hit stores the hit voxel relative to the ray's voxel, counted along the ray's
// direction (9 bits per axis, +2), and the hit face — compact, and independent of the world's
// size. Rays are limited to CACHE_MAX_RAY_LENGTH voxels so the offsets fit.
#ifndef SHARED_IRRADIANCE_CACHE_H
#define SHARED_IRRADIANCE_CACHE_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint CACHE_FACES = 6u;
SHARED_CONST uint CACHE_MAX_DIRECTIONS = 256u;
// Rotated copies of the K-direction set in the directions buffer (set r at [r*K, (r+1)*K)); each
// entry picks one, and one of 8 mirrors of it, by a hash of its key and the lighting seed.
SHARED_CONST uint CACHE_DIRECTION_SETS = 64u;
SHARED_CONST float CACHE_MAX_RAY_LENGTH = 500.0f;
SHARED_CONST uint CACHE_HIT_MISS = 0xFFFFFFFFu;
SHARED_CONST uint CACHE_HIT_DYNAMIC = 0x80000000u;
SHARED_CONST uint CACHE_HIT_FACE_MASK = 7u;
SHARED_CONST uint CACHE_SET_STATIC = 0u;
SHARED_CONST uint CACHE_SET_DYNAMIC = 1u;
SHARED_CONST uint CACHE_TABLE_EMPTY = 0xFFFFFFFFu;
SHARED_CONST float CACHE_RAY_OFFSET = 0.501f;  // rays start just outside the face, at its centre
SHARED_CONST uint CACHE_GROUP_SIZE = 64u;
SHARED_CONST uint CACHE_DISPATCH_ROW = 65535u * CACHE_GROUP_SIZE;  // threads per dispatch row

struct CacheParams {
    uvec4 counts;  // x: entries to update, y: entries to trace statically, z: K directions, w: rays per face per update
    uvec4 frame;   // x: frame index (also the rotation through the K directions), y: unused, z: bounces, w: lighting seed (also picks each entry's direction set)
    vec4 blend;    // x: alpha, y: max ray length, z: scene time (s), w: dynamic fade (s)
    uvec4 table;   // x: hash table buckets - 1 (a power of two minus one), y: slot capacity, z: flags
    uvec4 image;   // x width, y height, z: static entries (they come first in the update list)
};
SHARED_ASSERT_SIZE(CacheParams, 80);

SHARED_CONST uint CACHE_FLAG_NO_FILTER = 1u;
SHARED_CONST uint CACHE_FLAG_FULL_RETRACE = 2u;  // tests and benchmarks: the static set re-traces everything (visibility_static_full.comp)

struct CacheEntry {
    ivec4 voxel;  // xyz world voxel, w set (CACHE_SET_*)
    vec4 time;    // x: scene time of its last update (s), y: 1 in the frame the slot was (re)assigned
};
SHARED_ASSERT_SIZE(CacheEntry, 32);

// One hash-table bucket: the key (voxel, set) and its slot. Key x = CACHE_TABLE_EMPTY: unused.
struct CacheBucket {
    uvec4 keySlot;  // x: voxel.x | voxel.y << 16, y: voxel.z | set << 31, z: slot, w: unused
};
SHARED_ASSERT_SIZE(CacheBucket, 16);

SHARED_END

#endif
