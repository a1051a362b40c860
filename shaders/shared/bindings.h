// Descriptor bindings every ray-tracing pass shares: the world (set 0, bindings 0-3).
// A pass's own buffers start at PASS_BINDING_FIRST. All bindings are storage buffers.
#ifndef SHARED_BINDINGS_H
#define SHARED_BINDINGS_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint WORLD_BINDING_INFO = 0u;     // BrickGridInfo
SHARED_CONST uint WORLD_BINDING_CELLS = 1u;    // uint per top-grid cell
SHARED_CONST uint WORLD_BINDING_PAGES = 2u;    // uint64 device address per brick page
SHARED_CONST uint WORLD_BINDING_PALETTE = 3u;  // GpuMaterial per material id
SHARED_CONST uint WORLD_BINDING_COUNT = 4u;
SHARED_CONST uint PASS_BINDING_FIRST = 4u;

// Passes that sample lights add the emitter list after the world (bindings 4-7) and start their
// own buffers at LIT_PASS_BINDING_FIRST.
SHARED_CONST uint LIGHTS_BINDING_INFO = 4u;      // EmitterListInfo
SHARED_CONST uint LIGHTS_BINDING_EMITTERS = 5u;  // GpuEmitter per slot
SHARED_CONST uint LIGHTS_BINDING_ALIVE = 6u;     // uint slot per alive emitter
SHARED_CONST uint LIGHTS_BINDING_ALIAS = 7u;     // AliasEntry per alive emitter
SHARED_CONST uint LIT_PASS_BINDING_FIRST = 8u;

SHARED_END

#endif
