#version 460
// Temporal upsampling's pre-pass, per render pixel: what the resolve needs of the 3x3 render
// samples around a display pixel's nearest sample, computed once per render pixel instead of at
// every display pixel that sample is nearest to (256 of them at scale 1/16). The colour spread the
// resolve clips the history to (mean and standard deviation in YCoCg, and the range), the distinct
// surface keys its disocclusion test looks for, and the sample's own motion and edit flag —
// packed into UPSAMPLING_NEIGHBOURHOOD_TEXELS uvec4 texels (shared/upsampling.h), which the
// resolve reads where it read 9 radiance, 9 key and 3 G-buffer texels.
#extension GL_GOOGLE_include_directive : require

#include "common/gbuffer_load.glsl"
#include "common/ycocg.glsl"
#include "shared/frame_params.h"
#include "shared/upsampling.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = NEIGHBOURHOOD_BINDING_FRAME, std430) readonly buffer Frame {
    FrameParams gFrame;
};
layout(set = 0, binding = NEIGHBOURHOOD_BINDING_PARAMS, std430) readonly buffer Params {
    UpsamplingParams gParams;
};
layout(set = 0, binding = NEIGHBOURHOOD_BINDING_GBUFFER) uniform usamplerBuffer gGBuffer;
layout(set = 0, binding = NEIGHBOURHOOD_BINDING_RADIANCE) uniform samplerBuffer gRadiance;
layout(set = 0, binding = NEIGHBOURHOOD_BINDING_SURFACE_KEYS) uniform usamplerBuffer gSurfaceKeys;
layout(set = 0, binding = NEIGHBOURHOOD_BINDING_OUT, std430) writeonly buffer Summary {
    uvec4 gSummary[];
};

// Half floats rounded away from the box they bound (half of 2^-10 relative at most, and the
// subnormals' absolute step), so a packed box never shrinks: a still pixel's history lying on its
// neighbourhood's range must not be pulled in by the packing.
uint packDown(vec2 v) { return packHalf2x16(v - abs(v) * (1.0 / 1024.0) - 6.0e-8); }
uint packUp(vec2 v) { return packHalf2x16(v + abs(v) * (1.0 / 1024.0) + 6.0e-8); }

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 render = ivec2(gFrame.imageSize.xy);
    if (any(greaterThanEqual(pixel, render))) return;
    uint index = uint(pixel.x + pixel.y * render.x);

    ivec3 columns = clamp(pixel.x + ivec3(-1, 0, 1), 0, render.x - 1);
    ivec3 rows = clamp(pixel.y + ivec3(-1, 0, 1), 0, render.y - 1);
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    vec3 lowest = vec3(1e30), highest = vec3(-1e30);
    uint ownKey = texelFetch(gSurfaceKeys, int(index)).x;
    uvec4 keys = uvec4(ownKey);  // the distinct keys; unused slots repeat the first
    uint keyCount = 1u;          // above four: more than four distinct
    for (int k = 0; k < 9; ++k) {
        int q = columns[k % 3] + rows[k / 3] * render.x;
        vec3 y = toYCoCg(max(texelFetch(gRadiance, q).rgb, vec3(0.0)));
        m1 += y;
        m2 += y * y;
        lowest = min(lowest, y);
        highest = max(highest, y);
        uint key = texelFetch(gSurfaceKeys, q).x;
        if (!any(equal(keys, uvec4(key)))) {
            if (keyCount < 4u) keys[keyCount] = key;
            ++keyCount;
        }
    }
    vec3 mean = m1 / 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));

    GBufferTexel surface = loadGBuffer(gGBuffer, index);
    uint flags = surface.motion.w > 0.0 ? NEIGHBOURHOOD_FLAG_MOTION : 0u;
    // An edit this frame near the surface: it may have kept its key (a plane) but not its
    // material or its light (a lamp turned to stone), and then its history is another surface's.
    if ((surface.data.w & GBUFFER_FLAG_DYNAMIC) == 0u &&
        all(greaterThanEqual(surface.voxel.xyz, gParams.editedMin.xyz)) &&
        all(lessThan(surface.voxel.xyz, gParams.editedMax.xyz)))
        flags |= NEIGHBOURHOOD_FLAG_EDITED;

    uint t = UPSAMPLING_NEIGHBOURHOOD_TEXELS * index;
    gSummary[t] = uvec4(floatBitsToUint(surface.motion.xy),
                        flags | (keyCount << NEIGHBOURHOOD_KEY_COUNT_SHIFT), 0u);
    gSummary[t + 1] = uvec4(floatBitsToUint(mean), packUp(sigma.xy));
    gSummary[t + 2] =
        uvec4((packUp(vec2(sigma.z)) & 0xffffu) | (packDown(vec2(lowest.x)) << 16),
              packDown(lowest.yz), packUp(highest.xy), packUp(vec2(highest.z)) & 0xffffu);
    gSummary[t + 3] = keys;
}
