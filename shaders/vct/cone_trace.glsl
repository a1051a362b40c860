// Diffuse cones through the radiance clipmap (shared/vct.h): shared by the per-pixel gather
// (trace_cones.comp) and the extra bounce (inject_radiance.comp), which read different volumes.
// The including shader defines VCT_VOLUME (the vec4 array) and VCT_ORIGIN(l) (that volume's
// level origins), and declares gVct and the world's bindings (common/scene_trace.glsl).
// Six 60-degree cones (Crassin et al., "Interactive Indirect Illumination Using Voxel Cone
// Tracing", 2011): one along the normal, five tilted 60 degrees from it; each cone's weight is
// its share of the cosine-weighted hemisphere (sin^2 30 = 1/4 for the normal cone), so the
// weighted sum of the cones' radiance is the cosine-weighted mean, i.e. E / pi.
#ifndef VCT_CONE_TRACE_GLSL
#define VCT_CONE_TRACE_GLSL

#include "common/scene_trace.glsl"
#include "shared/vct.h"

const uint kVctCones = 6u;
const float kVctConeTan = 0.57735027;  // tan 30 degrees: the cones' half-angle
const float kVctStopOpacity = 0.95;

vec3 vctConeDirection(vec3 n, uint i) {
    if (i == 0u) return n;
    vec3 t = abs(n.x) > 0.5 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 b1 = normalize(cross(n, t));
    vec3 b2 = cross(n, b1);
    float phi = 2.0 * PI * float(i - 1u) / 5.0;
    return normalize(n * 0.5 + (b1 * cos(phi) + b2 * sin(phi)) * 0.8660254);
}

float vctConeWeight(uint i) { return i == 0u ? 0.25 : 0.15; }

// Where a level's texel lives: its world texel coordinate modulo VCT_RES (shared/vct.h).
uint vctTexelBase(uint level, ivec3 worldTexel) {
    uvec3 p = uvec3(((worldTexel % int(VCT_RES)) + int(VCT_RES)) % int(VCT_RES));
    return (level * VCT_TEXELS_PER_LEVEL + p.x + VCT_RES * (p.y + VCT_RES * p.z)) * VCT_SLOTS;
}

// One texel (c: in the level's window) seen by a cone travelling along `dir`: its axis slots'
// radiance weighted by dir^2 (they sum to 1), premultiplied by coverage; zero outside the level.
vec4 vctTexel(uint level, ivec3 c, vec3 w, uvec3 slot) {
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(int(VCT_RES))))) return vec4(0.0);
    ivec4 o = VCT_ORIGIN(level);
    uint base = vctTexelBase(level, o.xyz / o.w + c);
    vec4 x = VCT_VOLUME[base + slot.x], y = VCT_VOLUME[base + slot.y], z = VCT_VOLUME[base + slot.z];
    // Opacity: the largest of the axis coverages, not their weighted mean — a diagonal cone
    // crossing a one-voxel wall is stopped by it, not let through half-strength (the leak the
    // mean gave). Isotropic texels have one value in every slot, so it changes nothing there.
    return vec4(w.x * x.rgb + w.y * y.rgb + w.z * z.rgb, max(x.a, max(y.a, z.a)));
}

// Trilinear over the level's texel centres, leaving out the texels not wholly in front of the
// plane the cones start from (point `p0`, normal `n0`, an axis) and renormalising over the rest.
// Those texels hold the cone's own surface: the hemisphere above a face never sees it, but a cone
// that grazes the face's plane (the five tilted ones: 60 degrees off the normal, 30 wide) takes
// it into every trilinear footprint, as an occluder as opaque as a wall — the cones met their
// own surface and an open floor gathered half its sky (Vct.OpenFloorGathersItsSky).
vec4 vctSample(uint level, vec3 pos, vec3 dir, vec3 p0, vec3 n0) {
    ivec4 o = VCT_ORIGIN(level);
    vec3 u = (pos - vec3(o.xyz)) / float(o.w) - 0.5;
    ivec3 c0 = ivec3(floor(u));
    vec3 f = u - vec3(c0);
    vec3 w = dir * dir;
    uvec3 slot = uvec3(0u, 2u, 4u) + uvec3(greaterThan(dir, vec3(0.0)));
    vec4 s = vec4(0.0);
    float weight = 0.0;
    for (int i = 0; i < 8; ++i) {
        ivec3 d = ivec3(i & 1, (i >> 1) & 1, i >> 2);
        vec3 centre = vec3(o.xyz) + (vec3(c0 + d) + 0.5) * float(o.w);
        if (dot(centre - p0, n0) < 0.5 * float(o.w) - 1.0e-3) continue;
        vec3 t = mix(1.0 - f, f, vec3(d));
        float tw = t.x * t.y * t.z;
        s += tw * vctTexel(level, c0 + d, w, slot);
        weight += tw;
    }
    return weight > 0.0 ? s / weight : vec4(0.0);
}

// Inside the level, half a texel from its border (so the trilinear footprint is in it).
bool vctInside(uint level, vec3 pos) {
    ivec4 o = VCT_ORIGIN(level);
    vec3 u = (pos - vec3(o.xyz)) / float(o.w);
    return all(greaterThanEqual(u, vec3(0.5))) && all(lessThanEqual(u, vec3(float(VCT_RES) - 0.5)));
}

// What a cone sees past the clipmap, from `pos`, the last point it sampled inside it (its next
// step, a cone diameter on, may have jumped walls): the sky if it has left the world too (a ray
// that leaves the world's box never re-enters it), else the sky only if a ray on from `pos` meets
// no voxel. The clipmap holds no radiance out there, so a wall past its reach
// gives nothing rather than the sky behind it: a room outside the coarsest level took the sky
// through its own walls (Vct.DoorwayLitRoomCeiling: 15x the path tracer's ceiling).
vec3 vctBeyondClipmap(vec3 pos, vec3 dir, vec3 sky) {
    bool inWorld = all(greaterThanEqual(pos, vec3(0.0))) && all(lessThan(pos, vec3(gridSizeInVoxels(false))));
    if (!inWorld) return sky;
    return traceScene(pos, dir, 1.0e30).hit ? vec3(0.0) : sky;
}

// Radiance arriving at `origin` from within the cone about `dir`: front-to-back accumulation of
// the texels' premultiplied radiance and opacity (opacity corrected to the step length), level
// chosen by the cone's diameter, until it is opaque; what is left sees the sky, or nothing where
// the world goes on past the clipmap and blocks it (vctBeyondClipmap).
vec3 vctTraceCone(vec3 origin, vec3 dir, vec3 sky, vec3 p0, vec3 n0) {
    const float s0 = float(VCT_BASE_TEXEL);
    const uint levels = clamp(gVct.levels, 1u, VCT_MAX_LEVELS);
    float t = s0, tSampled = 0.0;
    vec3 c = vec3(0.0);
    float a = 0.0;
    for (uint step = 0u; step < 64u && a < kVctStopOpacity; ++step) {
        float diameter = max(s0, 2.0 * kVctConeTan * t);
        float lod = log2(diameter / s0);
        vec3 pos = origin + dir * t;
        uint level = min(uint(lod), levels - 1u);
        while (level < levels && !vctInside(level, pos)) ++level;
        if (level >= levels) return c + (1.0 - a) * vctBeyondClipmap(origin + dir * tSampled, dir, sky);
        // One level per step (the finer one that holds the cone), stepped by a cone diameter:
        // a quarter of the reads of blending two levels at half-diameter steps, which on a CPU
        // device cost more than the rest of the frame.
        vec4 s = vctSample(level, pos, dir, p0, n0);
        float stepLength = diameter;
        if (s.a > 1.0e-6) {
            float texel = float(VCT_ORIGIN(level).w);
            float alpha = 1.0 - pow(max(1.0 - min(s.a, 1.0), 0.0), stepLength / texel);
            c += (1.0 - a) * s.rgb * (alpha / s.a);
            a += (1.0 - a) * alpha;
        }
        tSampled = t;
        t += stepLength;
    }
    // Stopped by what it met: the little it lets through is taken as more of the same, not the
    // sky (which gave every cone stopped by a wall 5 % of the sky: a closed room lit by it).
    return a >= kVctStopOpacity ? c / a : c + (1.0 - a) * sky;
}

// The cosine-weighted mean of the incoming radiance over the hemisphere about `n` at `p`
// (times the albedo, the reflected radiance); `offset` voxels off the surface along n.
vec3 vctGather(vec3 p, vec3 n, float offset, FrameParams frame) {
    vec3 origin = p + n * offset;
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < kVctCones; ++i) {
        vec3 dir = vctConeDirection(n, i);
        sum += vctConeWeight(i) * vctTraceCone(origin, dir, skyBackground(frame, dir), p, n);
    }
    return sum;
}

#endif
