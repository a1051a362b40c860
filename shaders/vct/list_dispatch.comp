#version 460
// Voxel cone tracing's injection, second dispatch: the workgroup count of vct.inject's indirect
// dispatch, from the length of the list vct.classify built (shared/vct.h).
#extension GL_GOOGLE_include_directive : require

#include "vct/inject_common.glsl"

layout(local_size_x = 1) in;

void main() {
    gList[VCT_LIST_ARGS] = (gList[VCT_LIST_COUNT] + VCT_INJECT_GROUP_SIZE - 1u) / VCT_INJECT_GROUP_SIZE;
    gList[VCT_LIST_ARGS + 1u] = 1u;
    gList[VCT_LIST_ARGS + 2u] = 1u;
}
