// The irradiance cache's buffers and the helpers its passes share. Every cache pass binds the
// same list (after the world and the lights), so one layout serves them all. Layouts and the
// packing of hits: shared/irradiance_cache.h.
#ifndef IRRADIANCE_CACHE_IRRADIANCE_CACHE_GLSL
#define IRRADIANCE_CACHE_IRRADIANCE_CACHE_GLSL

#include "common/direct_light.glsl"
#include "common/scene_trace.glsl"
#include "shared/gbuffer.h"
#include "shared/irradiance_cache.h"

layout(set = 0, binding = CACHE_BINDING_PARAMS, std430) readonly buffer CacheParamsBuffer { CacheParams gCache; };
layout(set = 0, binding = CACHE_BINDING_FRAME, std430) readonly buffer FrameParamsBuffer { FrameParams gFrame; };
layout(set = 0, binding = CACHE_BINDING_DIRECTIONS, std430) readonly buffer Directions { vec4 gDirections[]; };
layout(set = 0, binding = CACHE_BINDING_ENTRIES, std430) readonly buffer Entries { CacheEntry gEntries[]; };
layout(set = 0, binding = CACHE_BINDING_TABLE, std430) readonly buffer Table { CacheBucket gTable[]; };
// [0, updates): slots to update; [capacity, capacity + traces): slots to trace statically; then
// the face lists faces.comp writes (cacheListedFace).
layout(set = 0, binding = CACHE_BINDING_LISTS, std430) buffer Lists { uint gLists[]; };
layout(set = 0, binding = CACHE_BINDING_STATIC_HITS, std430) buffer StaticHits { uint gStaticHits[]; };
layout(set = 0, binding = CACHE_BINDING_SELECTED_HITS, std430) buffer SelectedHits { uint gSelectedHits[]; };
layout(set = 0, binding = CACHE_BINDING_IRRADIANCE, std430) buffer Irradiance { vec4 gIrradiance[]; };
layout(set = 0, binding = CACHE_BINDING_FILTERED, std430) buffer Filtered { vec4 gFiltered[]; };
layout(set = 0, binding = CACHE_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;  // loadGBuffer (common/surface.glsl)
layout(set = 0, binding = CACHE_BINDING_RADIANCE, std430) buffer Radiance { vec4 gRadiance[]; };
layout(set = 0, binding = CACHE_BINDING_INDIRECT, std430) writeonly buffer Indirect { vec4 gIndirect[]; };
layout(set = 0, binding = CACHE_BINDING_COUNTERS, std430) buffer Counters { uint gCounters[CACHE_COUNTER_COUNT]; };
layout(set = 0, binding = CACHE_BINDING_LATE_PIXELS, std430) buffer LatePixels { uint gLatePixels[]; };

uint cacheThread() { return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * CACHE_DISPATCH_ROW; }

// The faces with work this frame (faces.comp), so that the passes with ray loops run one
// invocation per such face: lavapipe runs 8 invocations in lockstep, and with one per face of
// every entry a ground voxel's closed faces idled through the loops of its open ones. Each list
// holds item * CACHE_FACES + face, its length in a counter (reset to 0 every frame); the host
// sizes the lists buffer for them (kListWordsPerSlot in irradiance_cache.cpp).
//   CACHE_LIST_STATIC   exposed faces of the static updates      at 2 * capacity
//   CACHE_LIST_DYNAMIC  exposed faces of the dynamic updates    at 2 * capacity + 6 * staticUpdates
//   CACHE_LIST_TRACE    exposed faces of the trace list (item: index into it)   at 8 * capacity
const uint CACHE_LIST_STATIC = 1u, CACHE_LIST_DYNAMIC = 2u, CACHE_LIST_TRACE = 3u;  // also their counters' indices

// A dynamic entry's static hit not traced yet: its face was covered by an object's voxel on the
// first update of the phase (never a packed hit: face bits 7 are FACE_NONE).
const uint CACHE_HIT_UNTRACED = 0x7FFFFFFFu;

uint cacheListBase(uint list) {
    if (list == CACHE_LIST_STATIC) return 2u * gCache.capacity;
    if (list == CACHE_LIST_DYNAMIC) return 2u * gCache.capacity + CACHE_FACES * gCache.staticUpdates;
    return 8u * gCache.capacity;
}

// Entry i of `list` as (item, face); false past its end.
bool cacheListedFace(uint list, uint i, out uint item, out uint face) {
    item = 0u;
    face = 0u;
    if (i >= gCounters[list]) return false;
    uint code = gLists[cacheListBase(list) + i];
    item = code / CACHE_FACES;
    face = code % CACHE_FACES;
    return true;
}

// Thread `thread` of a pass over both update lists (the bounce, the filter): the static list's
// faces, then the dynamic list's.
bool cacheUpdateListedFace(uint thread, out uint item, out uint face) {
    uint staticFaces = gCounters[CACHE_LIST_STATIC];
    return thread < staticFaces ? cacheListedFace(CACHE_LIST_STATIC, thread, item, face)
                                : cacheListedFace(CACHE_LIST_DYNAMIC, thread - staticFaces, item, face);
}

// Which of the rotated direction sets entry (voxel, set) uses, and how it is mirrored: a hash of
// the key and the lighting seed, so neighbours' finite sets err independently and a run repeats
// exactly. IrradianceCache::directionRotation is the host's copy.
// The hash table's key words of (voxel, set, coarse): IrradianceCacheDirectory's keyWords.
uvec2 cacheKeyWords(ivec3 voxel, uint set, uint coarse) {
    return uvec2(uint(voxel.x) | (uint(voxel.y) << 16u), uint(voxel.z) | (coarse << CACHE_KEY_COARSE_SHIFT) | (set << 31u));
}

uint cacheRotation(ivec3 voxel, uint set, uint coarse) {
    uvec2 key = cacheKeyWords(voxel, set, coarse);
    return pcgHash(key.x ^ pcgHash(key.y ^ pcgHash(gCache.seed ^ 0x9E3779B9u)));
}
uint cacheEntryRotation(CacheEntry e) { return cacheRotation(e.voxel.xyz, uint(e.voxel.w), e.coarse); }

// Direction k of face `face` of an entry with rotation `rotation`, in world space. The set comes
// from the host's table; the mirror (swap, negations) and the face frame only permute and negate
// components, so host and GPU get the same bits and the cosine distribution is kept.
vec3 cacheDirection(uint rotation, uint face, uint k) {
    vec3 local = gDirections[(rotation % CACHE_DIRECTION_SETS) * gCache.directions + k].xyz;
    uint mirror = rotation >> 29u;
    if ((mirror & 1u) != 0u) local.xy = local.yx;
    if ((mirror & 2u) != 0u) local.x = -local.x;
    if ((mirror & 4u) != 0u) local.y = -local.y;
    uint axis = face >> 1u;
    vec3 d;
    d[(axis + 1u) % 3u] = local.x;
    d[(axis + 2u) % 3u] = local.y;
    d[axis] = (face & 1u) != 0u ? local.z : -local.z;
    return d;
}

vec3 cacheRayOrigin(ivec3 voxel, uint face) {
    vec3 o = vec3(voxel) + 0.5;
    uint axis = face >> 1u;
    o[axis] += (face & 1u) != 0u ? CACHE_RAY_OFFSET : -CACHE_RAY_OFFSET;
    return o;
}

// A coarse entry's rays start at the centre of its 2x2 patch (the corner its four voxels share),
// just outside the face, in the open space in front of the patch.
vec3 cacheEntryRayOrigin(CacheEntry e, uint face) {
    vec3 o = cacheRayOrigin(e.voxel.xyz, face);
    if (e.coarse != 0u) {
        uint axis = face >> 1u;
        o[(axis + 1u) % 3u] += 0.5;
        o[(axis + 2u) % 3u] += 0.5;
    }
    return o;
}

// The direction index the j-th ray of an entry's update uses: the entry's phase advances with its
// own updates, so all K are covered every K/S updates however often the budget picks it.
uint cacheDirectionIndex(uint phase, uint j) {
    return j * (gCache.directions / gCache.raysPerUpdate) + phase;
}

// The hit voxel's offset from the ray's voxel, counted along the ray's direction on each axis
// (a ray only moves forward): 9 bits then reach CACHE_MAX_RAY_LENGTH voxels, enough to cross a
// 256-voxel room. A ray cut short is taken for the sky, so it must reach the far wall.
uint packCacheHit(ivec3 origin, ivec3 voxel, uint face, bool dynamicSet, vec3 d) {
    ivec3 sgn = ivec3(lessThan(d, vec3(0.0))) * -2 + 1;
    uvec3 rel = uvec3(clamp((voxel - origin) * sgn + 2, 0, 511));
    return rel.x | (rel.y << 9u) | (rel.z << 18u) | (face << 27u) | (dynamicSet ? CACHE_HIT_DYNAMIC : 0u);
}
ivec3 cacheHitVoxel(ivec3 origin, uint packed, vec3 d) {
    ivec3 sgn = ivec3(lessThan(d, vec3(0.0))) * -2 + 1;
    return origin + (ivec3(int(packed & 511u), int((packed >> 9u) & 511u), int((packed >> 18u) & 511u)) - 2) * sgn;
}
uint cacheHitFace(uint packed) { return (packed >> 27u) & CACHE_HIT_FACE_MASK; }

// A face is worth caching when light can reach it: its neighbour is not static solid.
bool cacheFaceExposed(ivec3 voxel, uint face, uint set) {
    ivec3 n = voxel + faceNormal(face);
    if (staticVoxelSolid(n)) return false;
    return set == CACHE_SET_STATIC || !dynamicVoxelSolid(n);
}

// The coarse key (cacheKeyWords' `coarse` = 1 + face, at the patch's lowest voxel) of `face` of
// static voxel `voxel` when its 2x2 patch is open — four static voxels in one plane, aligned to
// even coordinates, the four voxels in front of them empty — else 0. The host's rule:
// render/irradiance_cache/cache_lod.cpp, coarsePatchKey.
uint cacheCoarsePatch(ivec3 voxel, uint face, out ivec3 base) {
    uint axis = face >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
    base = voxel;
    base[ua] &= ~1;
    base[va] &= ~1;
    ivec3 n = faceNormal(face);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            ivec3 v = base;
            v[ua] += i;
            v[va] += j;
            if (!staticVoxelSolid(v) || staticVoxelSolid(v + n)) return 0u;
        }
    }
    return 1u + face;
}

// Whether the open space in front of `face` of `voxel` reaches the front of the same face of its
// in-plane neighbour at offset `d` (along the plane's u, v axes): a 4-connected walk through the
// layer of voxels in front, along u then v or along v then u, that meets no solid voxel. A wall
// between two faces of one plane, however thin, stands in that layer, so the gather's fallback
// never reads light from its other side.
bool cacheFrontOpen(ivec3 v, uint set) {
    return !staticVoxelSolid(v) && (set == CACHE_SET_STATIC || !dynamicVoxelSolid(v));
}
bool cacheFrontWalkOpen(ivec3 front, uint ua, uint va, ivec2 d, bool uFirst, uint set) {
    ivec2 steps = abs(d), dir = sign(d);
    ivec3 v = front;
    for (int k = 0; k < steps.x + steps.y; ++k) {
        if (uFirst ? k < steps.x : k >= steps.y) v[ua] += dir.x;
        else v[va] += dir.y;
        if (!cacheFrontOpen(v, set)) return false;
    }
    return true;
}
bool cacheFrontsConnected(ivec3 voxel, uint face, ivec2 d, uint set) {
    uint axis = face >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
    ivec3 front = voxel + faceNormal(face);
    return cacheFrontWalkOpen(front, ua, va, d, true, set) || cacheFrontWalkOpen(front, ua, va, d, false, set);
}

// Whether an entry's face is worth updating: a voxel's exposed faces; a coarse entry's one face
// while its patch is still open (an edit may have closed it).
bool cacheEntryFaceExposed(CacheEntry e, uint face) {
    if (e.coarse == 0u) return cacheFaceExposed(e.voxel.xyz, face, uint(e.voxel.w));
    ivec3 base;
    return e.coarse == 1u + face && cacheCoarsePatch(e.voxel.xyz, face, base) == e.coarse;
}

// Slot of (voxel, set, coarse), or ~0u. Same hash and probing as IrradianceCacheDirectory::buildTable.
uint cacheLookupKey(ivec3 voxel, uint set, uint coarse) {
    if (any(lessThan(voxel, ivec3(0))) || any(greaterThan(voxel, ivec3(0xFFFF)))) return ~0u;
    uvec2 key = cacheKeyWords(voxel, set, coarse);
    uint mask = gCache.tableMask;
    uint b = pcgHash(key.x ^ pcgHash(key.y)) & mask;
    for (uint i = 0u; i <= mask; ++i) {
        uvec4 e = gTable[b].keySlot;
        if (e.x == CACHE_TABLE_EMPTY) return ~0u;
        if (e.x == key.x && e.y == key.y) return e.z;
        b = (b + 1u) & mask;
    }
    return ~0u;
}
uint cacheLookup(ivec3 voxel, uint set) { return cacheLookupKey(voxel, set, 0u); }

// A dynamic entry's irradiance dims linearly to zero over the fade time after its last update;
// a static one's never does (its entry is not read).
float cacheFade(uint slot, uint set) {
    if (set == CACHE_SET_STATIC) return 1.0;
    return clamp(1.0 - (gCache.time - gEntries[slot].updatedAt) / gCache.fadeSeconds, 0.0, 1.0);
}

#endif
