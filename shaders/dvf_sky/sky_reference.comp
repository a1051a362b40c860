#version 460
// The sky term's ground truth (`--sky reference`): per pixel, cosine-sampled rays from the
// G-buffer's surface; each that escapes the world brings albedo x sky radiance in its direction
// (cosine sampling cancels cos / pi). That is the sky's direct light — the path tracer's first
// bounce when it escapes — without interreflection. A running sum per pixel while the camera and
// world stay still (DVF_FLAG_RESTART drops it); adds its mean to the radiance, writes it alone.
#extension GL_GOOGLE_include_directive : require

#include "common/path_vertex.glsl"
#include "dvf_sky/dvf_sky.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    vec4 sum = (gDvf.flags & DVF_FLAG_RESTART) != 0u ? vec4(0.0) : gSky[index + gFrame.imageSize.x * gFrame.imageSize.y];
    Surface s = surfaceFrom(gGBuffer[index]);
    uint samples = max(gDvf.samples, 1u);
    uint rng = rngInit(pixel, gDvf.frame, 22u, gDvf.seed);
    for (uint i = 0u; i < samples; ++i) {
        vec3 L = vec3(0.0);
        if (s.valid) {
            vec3 dir = cosineDirection(s.normal, rngNext(rng), rngNext(rng));
            if (!traceScene(s.position + s.normal * kRayOffset, dir, 1.0e30).hit) L = s.albedo * skyBackground(gFrame, dir);
        }
        sum += vec4(L, 1.0);
    }
    gSky[index + gFrame.imageSize.x * gFrame.imageSize.y] = sum;
    vec3 term = sum.rgb / sum.w;
    gSky[index] = vec4(term, 1.0);
    gRadiance[index] += vec4(term, 0.0);
}
