#version 460
// Voxel cone tracing's injection, first dispatch: one workgroup per block of 4^3 texels the host
// listed (render/vct/vct_block_list.h: the blocks whose texels may need values their slots do not
// hold — new in their level and, while the rotation can change anything, those holding content or
// near the objects; empty space that stays in a level keeps its zeros and is not visited), one
// invocation per texel. It settles the texels that need no light — those that keep last frame's
// values stay (or are copied, when the extra bounce reads last frame's volume), empty ones (no
// occupied 8^3 cell) are zeroed — and lists the rest for vct.inject, dispatched over the list
// (vct.list_dispatch sizes it). Dispatched over every texel instead, the injection cost what the
// clipmap holds, not what it contains: on lavapipe a SIMD batch runs all the code it holds, rays
// and shading included, for every batch, though nearly every texel is empty or kept.
#extension GL_GOOGLE_include_directive : require

#include "vct/inject_common.glsl"

layout(local_size_x = VCT_BLOCK * VCT_BLOCK * VCT_BLOCK) in;

void main() {
    uint block = gBlocks[gl_WorkGroupID.x];
    uint level = block / VCT_BLOCKS_PER_LEVEL, b = block % VCT_BLOCKS_PER_LEVEL, i = gl_LocalInvocationIndex;
    uvec3 c = uvec3(b % VCT_BLOCKS_PER_AXIS, (b / VCT_BLOCKS_PER_AXIS) % VCT_BLOCKS_PER_AXIS, b / (VCT_BLOCKS_PER_AXIS * VCT_BLOCKS_PER_AXIS)) * VCT_BLOCK +
              uvec3(i % VCT_BLOCK, (i / VCT_BLOCK) % VCT_BLOCK, i / (VCT_BLOCK * VCT_BLOCK));
    uint index = c.x + VCT_RES * (c.y + VCT_RES * (c.z + VCT_RES * level));
    VctInjectTexel t = vctInjectTexel(index);
    if (vctKeepsPrevious(t)) {
        if ((gVct.flags & VCT_IN_PLACE) == 0u) {
            for (uint d = 0u; d < VCT_SLOTS; ++d) gVolume[t.base + d] = gPrevious[t.base + d];
        }
        return;
    }
    // Most texels are empty: their 8^3 cells first (one cell read for texels up to 8 voxels).
    if (!anyCellOccupied(t.minVoxel, t.size)) {
        for (uint d = 0u; d < VCT_SLOTS; ++d) gVolume[t.base + d] = vec4(0.0);
        return;
    }
    gList[VCT_LIST_HEADER + atomicAdd(gList[VCT_LIST_COUNT], 1u)] = index;
}
