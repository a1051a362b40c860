// Material palette entry, as uploaded to the GPU. Index 0 is "empty" and never shaded.
#ifndef SHARED_MATERIAL_H
#define SHARED_MATERIAL_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint MATERIAL_FLAG_EMISSIVE = 1u;

struct GpuMaterial {
    vec4 albedo;    // linear RGB, a unused
    vec4 emission;  // linear RGB radiance (colour x strength), a = strength
    uvec4 flags;    // x: MATERIAL_FLAG_*
};
SHARED_ASSERT_SIZE(GpuMaterial, 48);

SHARED_END

#endif
