// The voxel-face irradiance cache as the GPU sees it (engine/render/irradiance_cache/ keeps
// the CPU side). Entries are (voxel, set) pairs in slots; a hash table maps keys to slots.
//
// Per slot: CacheEntry; CACHE_FACES * K packed static hits (the static world's hits of its rays,
// traced S at a time over an entry's first K / S updates, for dynamic entries too);
// CACHE_FACES irradiance values, accumulated and filtered. Per entry in this frame's update list
// and per traced ray: the selected hit (static or dynamic, bit CACHE_HIT_DYNAMIC).
//
// A packed hit stores the hit voxel relative to the ray's voxel, counted along the ray's
// direction (9 bits per axis, +2), and the hit face — compact, and independent of the world's
// size. Rays are limited to CACHE_MAX_RAY_LENGTH voxels so the offsets fit.
#ifndef SHARED_IRRADIANCE_CACHE_H
#define SHARED_IRRADIANCE_CACHE_H
#include "bindings.h"
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

// Scalars only, so std430 lays them out as C++ does. Packed on the host by
// engine/render/irradiance_cache/cache_params.h.
struct CacheParams {
    uint updates;        // entries to update this frame
    uint traces;         // static entries that trace their phase's S directions this frame
    uint directions;     // K directions per face
    uint raysPerUpdate;  // S of the K, traced per face per update
    uint frameIndex;     // seeds the light sampling at the rays' hits
    uint bounces;
    uint seed;           // the lighting seed (also picks each entry's direction set)
    uint tableMask;      // hash table buckets - 1 (a power of two minus one)
    uint capacity;       // slots; the trace list starts at lists[capacity]
    uint flags;          // CACHE_FLAG_*
    uint width;          // image
    uint height;
    uint staticUpdates;  // static entries (they come first in the update list)
    float alpha;         // blend of a new estimate into the entry
    float maxRayLength;  // voxels
    float time;          // scene time (s)
    float fadeSeconds;   // dynamic entries fade over this long without an update
    float lodDistance;   // static faces at least this far (view distance, voxels) use 2x2 patch entries; 0: off
    uint fallbackRadius; // voxels the gather searches in a face's plane when a pixel's voxel has no entry yet; 0: off
    uint lightSamples;   // lit hits per face update whose direct light is sampled (weighted); 0: all
};
SHARED_ASSERT_SIZE(CacheParams, 80);

SHARED_CONST uint CACHE_FLAG_NO_FILTER = 1u;
SHARED_CONST uint CACHE_FLAG_FULL_RETRACE = 2u;  // tests and benchmarks: the static set re-traces everything (visibility_static_full.comp), and so do dynamic entries (visibility_dynamic_full.comp)

// Flags of an entry in this frame's update list (zero for entries not updated this frame).
SHARED_CONST uint CACHE_ENTRY_RESET = 1u;  // its running mean restarts: new slot, lights changed, or re-traced after an edit
SHARED_CONST uint CACHE_ENTRY_TRACE = 2u;  // tracing its phase's S directions through the static world: a static entry
                                           // (trace_static.comp), or a dynamic entry's first update of this phase

struct CacheEntry {
    ivec4 voxel;       // xyz world voxel, w set (CACHE_SET_*)
    float updatedAt;   // scene time of its last update (s)
    uint flags;        // CACHE_ENTRY_*, this frame
    uint phase;        // which S of the K directions this update uses: j * (K / S) + phase
    uint coarse;       // 0: a voxel's entry (six faces); 1 + face: a coarse entry, one face of an open 2x2 patch
};
SHARED_ASSERT_SIZE(CacheEntry, 32);

// Level of detail: a coarse entry covers one face of a 2x2 patch of static voxels in one plane,
// aligned to even coordinates, whose four voxels in front are empty (render/irradiance_cache/
// cache_lod.h). Its key is the patch's lowest voxel with `coarse` = 1 + face in key bits 27..29.
SHARED_CONST uint CACHE_KEY_COARSE_SHIFT = 27u;

// One hash-table bucket: the key (voxel, set, coarse) and its slot. Key x = CACHE_TABLE_EMPTY: unused.
struct CacheBucket {
    uvec4 keySlot;  // x: voxel.x | voxel.y << 16, y: voxel.z | coarse << 27 | set << 31, z: slot, w: unused
};
SHARED_ASSERT_SIZE(CacheBucket, 16);

// The bindings every cache pass shares (shaders/irradiance_cache/irradiance_cache.glsl), after
// the world and the emitter list.
SHARED_CONST uint CACHE_BINDING_PARAMS = LIT_PASS_BINDING_FIRST + 0u;         // CacheParams
SHARED_CONST uint CACHE_BINDING_FRAME = LIT_PASS_BINDING_FIRST + 1u;          // FrameParams
SHARED_CONST uint CACHE_BINDING_DIRECTIONS = LIT_PASS_BINDING_FIRST + 2u;     // vec4: CACHE_DIRECTION_SETS sets of K
SHARED_CONST uint CACHE_BINDING_ENTRIES = LIT_PASS_BINDING_FIRST + 3u;        // CacheEntry per slot
SHARED_CONST uint CACHE_BINDING_TABLE = LIT_PASS_BINDING_FIRST + 4u;          // CacheBucket
SHARED_CONST uint CACHE_BINDING_LISTS = LIT_PASS_BINDING_FIRST + 5u;          // update list, then trace list
SHARED_CONST uint CACHE_BINDING_STATIC_HITS = LIT_PASS_BINDING_FIRST + 6u;    // CACHE_FACES * K packed hits per slot
SHARED_CONST uint CACHE_BINDING_SELECTED_HITS = LIT_PASS_BINDING_FIRST + 7u;  // per updated entry and ray
SHARED_CONST uint CACHE_BINDING_IRRADIANCE = LIT_PASS_BINDING_FIRST + 8u;     // vec4 per slot and face
SHARED_CONST uint CACHE_BINDING_FILTERED = LIT_PASS_BINDING_FIRST + 9u;       // vec4 per slot and face
SHARED_CONST uint CACHE_BINDING_GBUFFER = LIT_PASS_BINDING_FIRST + 10u;       // GBufferTexel per pixel
SHARED_CONST uint CACHE_BINDING_RADIANCE = LIT_PASS_BINDING_FIRST + 11u;      // vec4 per pixel, read and written
SHARED_CONST uint CACHE_BINDING_INDIRECT = LIT_PASS_BINDING_FIRST + 12u;      // vec4 per pixel: the indirect term alone
SHARED_CONST uint CACHE_BINDING_COUNTERS = LIT_PASS_BINDING_FIRST + 13u;      // uint[CACHE_COUNTER_COUNT]
SHARED_CONST uint CACHE_BINDING_LATE_PIXELS = LIT_PASS_BINDING_FIRST + 14u;   // uint per pixel: gather_late's list

// The counters (reset to 0 every frame). 1..3 count the face lists (irradiance_cache.glsl).
SHARED_CONST uint CACHE_COUNTER_RAYS = 0u;  // rays the cache's passes traced this frame (not the bounce's shadow rays)
SHARED_CONST uint CACHE_COUNTER_LATE_PIXELS = 4u;  // pixels cache.gather left to cache.gather_late
// gather_late's workgroups as VkDispatchIndirectCommand (x, y, z), written by cache.gather.
SHARED_CONST uint CACHE_COUNTER_LATE_GROUPS = 5u;
SHARED_CONST uint CACHE_GATHER_LATE_GROUP_SIZE = 64u;
// The workgroups of the passes that run over the face lists, as VkDispatchIndirectCommand (x, y,
// z), written by cache.list_dispatch from the lists' lengths after cache.faces built them.
SHARED_CONST uint CACHE_COUNTER_ARGS_TRACE = 8u;     // cache.trace_static: the trace list's faces
SHARED_CONST uint CACHE_COUNTER_ARGS_STATIC = 11u;   // cache.visibility_static: the static updates' faces
SHARED_CONST uint CACHE_COUNTER_ARGS_DYNAMIC = 14u;  // cache.visibility_dynamic: the dynamic updates' faces
SHARED_CONST uint CACHE_COUNTER_ARGS_UPDATES = 17u;  // cache.bounce and cache.filter: both
SHARED_CONST uint CACHE_COUNTER_COUNT = 20u;

SHARED_END

#endif
