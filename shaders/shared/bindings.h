// Descriptor bindings every ray-tracing pass shares: the world (set 0, bindings 0-4).
// A pass's own buffers start at PASS_BINDING_FIRST. Bindings are storage buffers, but for those a
// shader declares usamplerBuffer (uniform texel buffers: top grid, page table, dynamic grid,
// emitters and alias table; the ReSTIR passes' G-buffer and the reservoirs they only read,
// restir.h). Passes number their own in their technique's header (restir.h, light_sampling.h,
// reference.h, ...); the passes every method shares, here. C++ binds by these numbers
// (render/passes/compute_pass.h).
#ifndef SHARED_BINDINGS_H
#define SHARED_BINDINGS_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint WORLD_BINDING_INFO = 0u;   // BrickGridInfo
SHARED_CONST uint WORLD_BINDING_CELLS = 1u;  // uint per top-grid cell, then per super cell
SHARED_CONST uint WORLD_BINDING_PAGES = 2u;  // uint64 device address per brick page (uvec2 texels)
SHARED_CONST uint WORLD_BINDING_PALETTE = 3u;  // GpuMaterial per material id
SHARED_CONST uint WORLD_BINDING_DYNAMIC = 4u;  // the dynamic grid (dynamic_grid.h), uint texels
SHARED_CONST uint WORLD_BINDING_COUNT = 5u;
SHARED_CONST uint PASS_BINDING_FIRST = 5u;

// Passes that sample lights add the emitter list after the world (bindings 5-8) and start their
// own buffers at LIT_PASS_BINDING_FIRST.
SHARED_CONST uint LIGHTS_BINDING_INFO = 5u;      // EmitterListInfo
SHARED_CONST uint LIGHTS_BINDING_EMITTERS = 6u;  // GpuEmitter per slot (3 uvec4 texels)
SHARED_CONST uint LIGHTS_BINDING_ALIVE = 7u;     // uint slot per alive emitter
SHARED_CONST uint LIGHTS_BINDING_ALIAS = 8u;     // AliasEntry per alive emitter (uvec4 texel)
SHARED_CONST uint LIT_PASS_BINDING_FIRST = 9u;

// Own bindings of the passes every method shares.
// world/primary_rays.comp
SHARED_CONST uint PRIMARY_BINDING_FRAME = PASS_BINDING_FIRST + 0u;  // FrameParams
SHARED_CONST uint PRIMARY_BINDING_GBUFFER =
    PASS_BINDING_FIRST + 1u;  // GBufferTexel per pixel, written
// uint per pixel, written: its surface key (common/surface_key.glsl), for the display's passes
SHARED_CONST uint PRIMARY_BINDING_SURFACE_KEYS = PASS_BINDING_FIRST + 2u;
// world/shade_sun.comp (preview shading)
SHARED_CONST uint SUN_BINDING_FRAME = PASS_BINDING_FIRST + 0u;      // FrameParams
SHARED_CONST uint SUN_BINDING_GBUFFER = PASS_BINDING_FIRST + 1u;    // GBufferTexel per pixel
SHARED_CONST uint SUN_BINDING_RADIANCE = PASS_BINDING_FIRST + 2u;   // vec4 per pixel, written
SHARED_CONST uint SUN_BINDING_RAY_STATS = PASS_BINDING_FIRST + 3u;  // uvec4 per pixel, written
// world/trace_rays_*.comp (batch ray queries)
SHARED_CONST uint TRACE_BINDING_PARAMS = PASS_BINDING_FIRST + 0u;  // TraceRaysParams
SHARED_CONST uint TRACE_BINDING_RAYS = PASS_BINDING_FIRST + 1u;    // TraceRayInput per ray
SHARED_CONST uint TRACE_BINDING_HITS = PASS_BINDING_FIRST + 2u;  // TraceRayOutput per ray, written
// post/tonemap.comp: no world
SHARED_CONST uint TONEMAP_BINDING_FRAME = 0u;     // FrameParams
SHARED_CONST uint TONEMAP_BINDING_RADIANCE = 1u;  // vec4 per pixel
SHARED_CONST uint TONEMAP_BINDING_LDR = 2u;       // packed RGBA8 per pixel, written
SHARED_CONST uint TONEMAP_BINDING_EXPOSURE =
    3u;  // ExposureState (shared/exposure.h), read when auto

SHARED_END

#endif
