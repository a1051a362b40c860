#version 460
// Injects the radiance clipmap (shared/vct.h), one listed texel per invocation, dispatched
// indirectly over the list vct.classify made of the texels that need light: those new in their
// level, near the dynamic objects or due in the rotation (one in refreshPeriod a frame) that hold
// an occupied cell — all such texels when the world, the lights, the sky or the settings changed
// (VCT_PREVIOUS_VALID off); vct.classify copied or zeroed the others. What is injected: the light
// the surfaces in the texel reflect from the sun and the emitters (common/direct_light.glsl's
// one-sample estimate, the one the cache and the path tracer use) — not their emission, which
// reaches the pixels as direct light. Per texel:
//  - coverage from the occupancy masks on a lattice of at most 4^3 blocks (voxels, 2^3 or 4^3
//    blocks, whichever the texel's size gives): per axis, the fraction of the texel's
//    cross-section some solid block covers (a one-voxel wall across the axis covers all of it);
//  - radiance per axis direction from one jittered ray crossing the texel along it (one ray, not
//    2x2, to keep the pass cheap on a CPU device): a ray travelling +x finds the surfaces
//    facing -x, the ones a cone travelling +x sees; a direction whose ray misses borrows the
//    texel's mean. The jitter is a hash of the texel's world position and the seed, not the
//    frame: a still scene injects the same values every frame (no flicker), and a texel's
//    values do not move with the camera. Each direction shades at most one surface point (one
//    sun and one emitter shadow ray).
// Without leak mitigation the texel is isotropic: the mean radiance of all its rays and the
// solid volume fraction as opacity in every slot.
#extension GL_GOOGLE_include_directive : require

#include "vct/inject_common.glsl"

layout(local_size_x = VCT_INJECT_GROUP_SIZE) in;

const uint kRaysPerSide = 1u;  // rays per axis direction: kRaysPerSide^2

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= gList[VCT_LIST_COUNT]) return;
    VctInjectTexel t = vctInjectTexel(gList[VCT_LIST_HEADER + i]);
    uint level = t.level, base = t.base;
    int size = t.size;
    ivec3 minVoxel = t.minVoxel;

    // Coverage: a lattice of n^3 blocks of b voxels.
    int n = min(size, 4), b = size / n;
    uint columnsX = 0u, columnsY = 0u, columnsZ = 0u, solid = 0u;
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                if (!blockSolid(minVoxel + ivec3(i, j, k) * b, b)) continue;
                ++solid;
                columnsX |= 1u << uint(j + n * k);
                columnsY |= 1u << uint(i + n * k);
                columnsZ |= 1u << uint(i + n * j);
            }
        }
    }
    if (solid == 0u) {
        for (uint d = 0u; d < VCT_SLOTS; ++d) gVolume[base + d] = vec4(0.0);
        return;
    }
    vec3 coverage = vec3(bitCount(columnsX), bitCount(columnsY), bitCount(columnsZ)) / float(n * n);
    float volumeFraction = float(solid) / float(n * n * n);

    // Radiance per direction. Seeded by the texel's world position (not the frame).
    uint rng = rngInit(uvec2(uint(minVoxel.x) ^ (level << 28u), uint(minVoxel.y)), uint(minVoxel.z), 80u, gVct.seed);
    const bool bounce = (gVct.flags & VCT_EXTRA_BOUNCE) != 0u && (gVct.flags & VCT_PREVIOUS_VALID) != 0u;
    const float eps = 1.0e-3;
    vec3 radiance[6];
    float hits[6];
    vec3 total = vec3(0.0);
    float totalHits = 0.0;
    for (uint d = 0u; d < VCT_SLOTS; ++d) {
        uint axis = d >> 1u;
        bool positive = (d & 1u) != 0u;
        vec3 dir = vec3(0.0);
        dir[axis] = positive ? 1.0 : -1.0;
        radiance[d] = vec3(0.0);
        hits[d] = 0.0;
        for (uint r = 0u; r < kRaysPerSide * kRaysPerSide; ++r) {
            vec2 cellUv = (vec2(r % kRaysPerSide, r / kRaysPerSide) + vec2(rngNext(rng), rngNext(rng))) / float(kRaysPerSide);
            vec3 origin = vec3(minVoxel);
            origin[(axis + 1u) % 3u] += cellUv.x * float(size);
            origin[(axis + 2u) % 3u] += cellUv.y * float(size);
            origin[axis] += positive ? -eps : float(size) + eps;
            SceneHit hit = traceScene(origin, dir, float(size) + 2.0 * eps);
            if (!hit.hit || hit.face >= 6u) continue;  // nothing, or the ray started inside a solid voxel
            Surface s = surfaceAt(hit, origin, dir);
            vec3 L = directLight(s, gFrame, rng);
            if (bounce) L += s.albedo * vctGather(s.position, s.normal, float(VCT_BASE_TEXEL) * gVct.startOffset, gFrame);
            radiance[d] += L;
            hits[d] += 1.0;
            break;
        }
        total += radiance[d];
        totalHits += hits[d];
    }
    vec3 mean = totalHits > 0.0 ? total / totalHits : vec3(0.0);
    const bool mitigate = (gVct.flags & VCT_LEAK_MITIGATION) != 0u;
    for (uint d = 0u; d < VCT_SLOTS; ++d) {
        if (!mitigate) {
            gVolume[base + d] = vec4(mean * volumeFraction, volumeFraction);
            continue;
        }
        // A direction whose rays all missed the solid part borrows the texel's mean.
        vec3 L = hits[d] > 0.0 ? radiance[d] / hits[d] : mean;
        float a = coverage[d >> 1u];
        gVolume[base + d] = vec4(L * a, a);
    }
}
