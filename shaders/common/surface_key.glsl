// A pixel's surface as the reconstruction compares pixels (shaders/denoiser/, shaders/upsampling/):
// the plane of its voxel face — the face's axis and sign and the plane's coordinate — exact,
// from the G-buffer's (voxel, face), where triangle renderers guess from depth and normal. Two
// pixels with the same key see one flat surface, so filter taps and history carry over between
// them; a different key is an edge. An object's voxels move between frames, so its key keeps only
// the face and the set.
#ifndef COMMON_SURFACE_KEY_GLSL
#define COMMON_SURFACE_KEY_GLSL

#include "shared/brick_grid.h"
#include "shared/gbuffer.h"

const uint SURFACE_KEY_SKY = 0xffffffffu;
const uint SURFACE_KEY_OBJECT = 0x80000000u;  // set in a dynamic object's keys

bool surfaceKeyIsObject(uint key) { return key != SURFACE_KEY_SKY && (key & SURFACE_KEY_OBJECT) != 0u; }

uint surfaceKey(GBufferTexel g) {
    uint face = uint(g.voxel.w);
    if (face >= 6u) return SURFACE_KEY_SKY;
    if ((g.data.w & GBUFFER_FLAG_DYNAMIC) != 0u) return SURFACE_KEY_OBJECT | face;
    uint axis = face >> 1u;
    int plane = g.voxel[axis] + int(face & 1u);
    return ((uint(plane) & 0x0fffffffu) << 3u) | face;
}

#endif
