#version 460
// DVF: takes this frame's batch off the trace queue for the build pass — at most the budget of
// masks, oldest first. One thread.
#extension GL_GOOGLE_include_directive : require

#include "dvf_sky/dvf_sky.glsl"

layout(local_size_x = 1) in;

void main() {
    uint waiting = gHeader.tail - gHeader.head;
    gHeader.batchStart = gHeader.head;
    gHeader.batchCount = min(waiting, gDvf.budget);
    gHeader.head += gHeader.batchCount;
    gHeader.tracedRays = 0u;
}
