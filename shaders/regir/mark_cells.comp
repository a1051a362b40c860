#version 460
// ReGIR: marks the grid cells this frame's visible surfaces lie in, so that build_cells fills only
// the cells some pixel will read (the cost follows the view, not the world's size).
#extension GL_GOOGLE_include_directive : require

#include "regir/regir.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = REGIR_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = REGIR_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = REGIR_BINDING_MARKS, std430) writeonly buffer Marks { uint gMarks[]; };
layout(set = 0, binding = REGIR_BINDING_GRID, std430) readonly buffer Grid { RegirGridInfo gGrid; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    Surface s = surfaceFrom(gGBuffer[pixel.x + pixel.y * gFrame.imageSize.x]);
    if (!s.valid) return;
    uint cell = regirSurfaceCell(gGrid, s);
    if (cell < gGrid.dims.w) gMarks[cell] = 1u;  // every writer stores the same value
}
