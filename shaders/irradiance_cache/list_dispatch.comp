#version 460
// Irradiance cache: the workgroup counts of the passes that run over the face lists, from the
// lists' lengths (cache.faces counted them), for their indirect dispatches. Dispatched for every
// face of every entry instead, most of their batches held only faces past a list's end — and on
// lavapipe such a batch still runs its shader's code once, ray loop and all, under an empty mask.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = 1) in;

// Workgroups of CACHE_GROUP_SIZE for `threads` in rows of 65535 (cacheThread undoes it), as the
// host's threadGroups.
void writeGroups(uint at, uint threads) {
    uint groups = (threads + CACHE_GROUP_SIZE - 1u) / CACHE_GROUP_SIZE;
    gCounters[at] = min(groups, 65535u);
    gCounters[at + 1u] = (groups + 65534u) / 65535u;
    gCounters[at + 2u] = 1u;
}

void main() {
    uint staticFaces = gCounters[CACHE_LIST_STATIC], dynamicFaces = gCounters[CACHE_LIST_DYNAMIC];
    writeGroups(CACHE_COUNTER_ARGS_TRACE, gCounters[CACHE_LIST_TRACE]);
    writeGroups(CACHE_COUNTER_ARGS_STATIC, staticFaces);
    writeGroups(CACHE_COUNTER_ARGS_DYNAMIC, dynamicFaces);
    writeGroups(CACHE_COUNTER_ARGS_UPDATES, staticFaces + dynamicFaces);
}
