// Temporal accumulation's parameters and bindings (shaders/accumulation/accumulate.comp). Packed
// on the host by engine/render/accumulation/accumulation.cpp.
#ifndef SHARED_ACCUMULATION_H
#define SHARED_ACCUMULATION_H
#include "interop.h"

SHARED_BEGIN

struct AccumulationParams {
    uint frames;  // frames in the running mean, this one included (1 = restart from this frame)
    uint pad0, pad1, pad2;
};
SHARED_ASSERT_SIZE(AccumulationParams, 16);

SHARED_CONST uint ACCUMULATION_BINDING_FRAME = 0u;    // FrameParams
SHARED_CONST uint ACCUMULATION_BINDING_PARAMS = 1u;   // AccumulationParams
SHARED_CONST uint ACCUMULATION_BINDING_HISTORY = 2u;  // vec4 per pixel: the mean so far
SHARED_CONST uint ACCUMULATION_BINDING_RADIANCE =
    3u;  // vec4 per pixel: this frame's, replaced by the mean

SHARED_END

#endif
