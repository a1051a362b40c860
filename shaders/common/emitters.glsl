// The emitter list (bindings 5-8) and the light-sampling maths shared by ReSTIR, the
// light-sampling baselines and the reference path tracer. Lights are axis-aligned cubes (a voxel
// or an 8^3 brick light) whose exposed faces emit radiance Le.
#ifndef COMMON_EMITTERS_GLSL
#define COMMON_EMITTERS_GLSL

#include "common/scene_trace.glsl"
#include "common/rng.glsl"
#include "shared/emitters.h"
#include "shared/restir.h"
#include "shared/shader_features.h"

layout(set = 0, binding = LIGHTS_BINDING_INFO, std430) readonly buffer LightInfoBuffer { EmitterListInfo gLights; };
// GpuEmitter per slot as three uvec4 texels (loadEmitter): candidates read emitters at lane-varying
// slots, which as storage-buffer reads would be a loop over the SIMD lanes each.
layout(set = 0, binding = LIGHTS_BINDING_EMITTERS) uniform usamplerBuffer gEmitterTexels;
layout(set = 0, binding = LIGHTS_BINDING_ALIVE, std430) readonly buffer AliveBuffer { uint gAlive[]; };
// AliasEntry per alive emitter, one uvec4 texel each: a texel fetch is a gather on llvmpipe, a
// storage-buffer read a loop over the SIMD lanes (common/world.glsl).
layout(set = 0, binding = LIGHTS_BINDING_ALIAS) uniform usamplerBuffer gAliasTexels;

// Off when no pass of the frame draws emitters uniformly / uses point mode: that code is compiled
// out (shared/shader_features.h).
layout(constant_id = FEATURE_UNIFORM_SAMPLING) const bool kUniformSampling = true;
layout(constant_id = FEATURE_POINT_LIGHTS) const bool kPointLights = true;

const float PI = 3.14159265358979;
const float kRayOffset = 1.0e-3;  // shadow rays start this far off the surface, along its normal

struct Surface {
    vec3 position;
    vec3 normal;
    vec3 albedo;
    vec3 emission;
    uint face;
    bool valid;  // a lit surface (not sky, not a camera inside solid)
};

GpuEmitter loadEmitter(uint slot) {
    int t = int(slot) * 3;
    return GpuEmitter(ivec4(texelFetch(gEmitterTexels, t)), uintBitsToFloat(texelFetch(gEmitterTexels, t + 1)),
                      texelFetch(gEmitterTexels, t + 2));
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// Is the emitter in this slot still the one the reservoir saw?
bool emitterCurrent(uint slot, uint generation) {
    if (slot == RESERVOIR_EMPTY || slot >= gLights.counts.y) return false;
    GpuEmitter e = loadEmitter(slot);
    return (e.info.w & EMITTER_FLAG_ALIVE) != 0u && e.info.y == generation;
}

// Probability of choosing emitter e as a candidate (the emitter already loaded).
float emitterPdfOf(GpuEmitter e, bool byPower) {
    if (byPower || !kUniformSampling) return e.radiance.w / gLights.power.x;
    return 1.0 / float(gLights.counts.x);
}

// Probability of choosing `slot` as a candidate.
float emitterPdf(uint slot, bool byPower) { return emitterPdfOf(loadEmitter(slot), byPower); }

// Draws an emitter slot uniformly or by power (alias table); false when there are no lights.
bool pickEmitter(inout uint rng, bool byPower, out uint slot) {
    byPower = byPower || !kUniformSampling;
    uint n = gLights.counts.x;
    slot = RESERVOIR_EMPTY;
    if (n == 0u || (byPower && !(gLights.power.x > 0.0))) return false;
    uint i = min(uint(rngNext(rng) * float(n)), n - 1u);
    if (byPower) {
        uvec4 a = texelFetch(gAliasTexels, int(i));  // probability, slot, alias, pdf
        slot = rngNext(rng) < uintBitsToFloat(a.x) ? a.y : a.z;
    } else {
        slot = gAlive[i];
    }
    return true;
}

// The per-lane select forms below (no vector indexed by a varying face or axis) matter on CPU
// Vulkan drivers (lavapipe), where a varying index becomes a store and a gather per lane; the
// values are the ones indexing gives.
bvec3 onAxis(uint axis) { return equal(uvec3(axis), uvec3(0u, 1u, 2u)); }
vec3 axisMask(uint axis) { return vec3(onAxis(axis)); }

vec3 faceNormalF(uint face) { return mix(vec3(0.0), vec3((face & 1u) != 0u ? 1.0 : -1.0), onAxis(face >> 1u)); }

// A point on face `face` of the emitter cube, at (u, v) in [0,1)^2 over the face.
vec3 emitterFacePoint(GpuEmitter e, uint face, vec2 uv) {
    float s = float(e.minCorner.w);
    uint axis = face >> 1u;
    vec3 offset = axisMask(axis) * ((face & 1u) != 0u ? s : 0.0) + axisMask((axis + 1u) % 3u) * (uv.x * s) +
                  axisMask((axis + 2u) % 3u) * (uv.y * s);
    return vec3(e.minCorner.xyz) + offset;
}

vec3 emitterCentre(GpuEmitter e) { return vec3(e.minCorner.xyz) + 0.5 * float(e.minCorner.w); }

// Thesis Alg. 1 weighs the six faces by the solid angle they subtend at x, estimated at the face
// centre (A cos / d^2), unexposed faces and faces turned away from x getting zero. A face is turned
// towards x only when x lies beyond its plane, so on each axis at most one face counts: the one
// returned in `faces` (its index), with its weight (0 when x is within the slab or the face is not
// exposed).
vec3 visibleFaceWeights(GpuEmitter e, vec3 x, out uvec3 faces) {
    float s = float(e.minCorner.w);
    vec3 lo = vec3(e.minCorner.xyz);
    vec3 hi = lo + s;
    bvec3 above = greaterThan(x, hi);
    faces = uvec3(0u, 2u, 4u) + uvec3(above);
    bvec3 beyond = bvec3(uvec3(above) | uvec3(lessThan(x, lo)));
    uvec3 exposed = (uvec3(e.info.x) >> faces) & 1u;
    vec3 plane = mix(lo, hi, above);
    vec3 centre = lo + 0.5 * s;
    vec3 w = vec3(0.0);
    for (int a = 0; a < 3; ++a) {  // unrolled: a is constant in every copy
        vec3 c = centre;
        c[a] = plane[a];
        vec3 d = c - x;
        float dist2 = max(dot(d, d), 1e-12);
        float cosine = abs(x[a] - plane[a]) * inversesqrt(dist2);
        w[a] = beyond[a] && exposed[a] != 0u ? s * s * cosine / dist2 : 0.0;
    }
    return w;
}

// Chooses a face by solid angle; returns its probability (0: no face is visible from x).
float pickFace(GpuEmitter e, vec3 x, float u, out uint face) {
    uvec3 faces;
    vec3 w = visibleFaceWeights(e, x, faces);
    float total = w.x + w.y + w.z;
    face = 0u;
    if (!(total > 0.0)) return 0.0;
    float target = u * total, running = 0.0, chosen = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (w[a] <= 0.0) continue;
        face = faces[a];
        chosen = w[a];
        running += w[a];
        if (target < running) break;
    }
    return chosen / total;
}

float facePdf(GpuEmitter e, vec3 x, uint face) {
    uvec3 faces;
    vec3 w = visibleFaceWeights(e, x, faces);
    float total = w.x + w.y + w.z;
    uint a = face >> 1u;
    float wa = a == 0u ? w.x : (a == 1u ? w.y : w.z);
    uint fa = a == 0u ? faces.x : (a == 1u ? faces.y : faces.z);
    return total > 0.0 && fa == face ? wa / total : 0.0;
}

// Point mode's light: a point at the centre of the emitter's exposed surface (the mean of its
// exposed faces' centres). For the usual lamp set into a wall or ceiling, one face is exposed and
// the point lies on it, where the area light's own centre is; a free-standing cube's is its centre.
vec3 emitterPointLight(GpuEmitter e) {
    vec3 sum = vec3(0.0);
    float faces = 0.0;
    for (uint f = 0u; f < 6u; ++f) {
        if ((e.info.x & (1u << f)) == 0u) continue;
        sum += emitterFacePoint(e, f, vec2(0.5));
        faces += 1.0;
    }
    return faces > 0.0 ? sum / faces : emitterCentre(e);
}

// Where point mode's shadow ray aims: the centre of the exposed face turned most towards x. A ray
// to the cube's centre (or to a point behind a face x cannot see) would cross the solid voxels
// around a flush lamp from more than about 45 degrees off its face and find it shadowed by its
// own wall; a ray to a face x is in front of reaches the emitter through that face.
vec3 emitterShadowTarget(GpuEmitter e, vec3 x) {
    vec3 best = emitterPointLight(e);
    float bestCosine = 0.0;
    for (uint f = 0u; f < 6u; ++f) {
        if ((e.info.x & (1u << f)) == 0u) continue;
        vec3 c = emitterFacePoint(e, f, vec2(0.5));
        float cosine = dot(faceNormalF(f), normalize(x - c));
        if (cosine > bestCosine) {
            bestCosine = cosine;
            best = c;
        }
    }
    return best;
}

// Unshadowed contribution (linear RGB radiance towards the camera) of a light sample at a
// diffuse surface. Area mode (face < 6): f = albedo/pi * Le * cos_x * cos_y / d^2, per unit
// light area. Point mode (face == LIGHT_FACE_CENTRE): the cube as a point light at the centre of
// its exposed surface with intensity Le x projected area of its exposed faces towards x.
// shadowDir and shadowDist give the ray lightVisible must trace: to the sample point in area mode,
// to emitterShadowTarget in point mode.
vec3 lightContribution(Surface s, GpuEmitter e, uint face, vec2 uv, out vec3 shadowDir, out float shadowDist) {
    bool point = face == LIGHT_FACE_CENTRE;
    if (!kPointLights && point) {  // a point-mode sample while point mode is compiled out: no light
        shadowDir = vec3(0.0, 0.0, 1.0);
        shadowDist = 0.0;
        return vec3(0.0);
    }
    point = kPointLights && point;
    vec3 y = point ? emitterPointLight(e) : emitterFacePoint(e, face, uv);
    vec3 d = y - s.position;
    float dist = length(d);
    vec3 toLight = d / max(dist, 1e-12);
    vec3 target = point ? emitterShadowTarget(e, s.position) : y;
    shadowDist = length(target - s.position);
    shadowDir = (target - s.position) / max(shadowDist, 1e-12);
    float cosX = dot(s.normal, toLight);
    if (!(dist > 1e-6) || cosX <= 0.0) return vec3(0.0);
    float geometry;
    if (point) {
        float side = float(e.minCorner.w);
        float projected = 0.0;
        for (uint f = 0u; f < 6u; ++f) {
            if ((e.info.x & (1u << f)) != 0u) projected += max(dot(faceNormalF(f), -toLight), 0.0);
        }
        geometry = side * side * projected * cosX / (dist * dist);
    } else {
        float cosY = dot(faceNormalF(face), -toLight);
        if (cosY <= 0.0) return vec3(0.0);
        geometry = cosX * cosY / (dist * dist);
    }
    return s.albedo / PI * e.radiance.rgb * geometry;
}

// Probability (density per unit area in area mode) with which the candidate sampler produces
// this light sample at x.
float lightSamplePdf(vec3 x, uint slot, uint face, bool byPower) {
    float p = emitterPdf(slot, byPower);
    if (face == LIGHT_FACE_CENTRE) return p;
    GpuEmitter e = loadEmitter(slot);
    float side = float(e.minCorner.w);
    return p * facePdf(e, x, face) / (side * side);
}

// Is the light sample visible from the surface? The first thing the shadow ray hits must be the
// emitter itself (or nothing before the sample point); emitters are static, so an object's voxel
// in the way occludes even inside the emitter's box.
// Whether a shadow ray towards emitter e reached it: it hit nothing, or the emitter's own voxels.
bool shadowHitReachesEmitter(SceneHit hit, GpuEmitter e) {
    if (!hit.hit) return true;
    if (hit.dynamicSet) return false;
    ivec3 lo = e.minCorner.xyz;
    return all(greaterThanEqual(hit.voxel, lo)) && all(lessThan(hit.voxel, lo + e.minCorner.w));
}

bool lightVisible(Surface s, GpuEmitter e, vec3 shadowDir, float shadowDist) {
    return shadowHitReachesEmitter(traceScene(s.position + s.normal * kRayOffset, shadowDir, shadowDist + kRayOffset), e);
}

#endif
