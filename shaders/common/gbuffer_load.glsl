// The G-buffer read as texels, for passes that only read it (and need nothing of the world).
#ifndef COMMON_GBUFFER_LOAD_GLSL
#define COMMON_GBUFFER_LOAD_GLSL

#include "shared/gbuffer.h"

// A GBufferTexel from an R32G32B32A32_UINT view of the G-buffer, four texels per pixel. The passes
// that only read the G-buffer bind it so: a texel fetch is one gather for the SIMD batch on llvmpipe,
// a storage-buffer read at a lane-varying index a loop over the lanes (docs/PERFORMANCE.md). Fields
// a caller does not use cost no fetch (the compiler drops it).
GBufferTexel loadGBuffer(usamplerBuffer texels, uint i) {
    int t = int(i) * 4;
    return GBufferTexel(ivec4(texelFetch(texels, t)), texelFetch(texels, t + 1), uintBitsToFloat(texelFetch(texels, t + 2)),
                        uintBitsToFloat(texelFetch(texels, t + 3)));
}

#endif
