// The path tracer's walk from one diffuse surface on: shared by the reference path tracer
// (shaders/reference/path_trace.comp, from the surface the camera ray hits) and the real-time
// indirect term (shaders/path_indirect/trace_paths.comp, from the G-buffer's surface's first
// bounce), so both estimate the same light the same way.
#ifndef COMMON_PATH_VERTEX_GLSL
#define COMMON_PATH_VERTEX_GLSL

#include "common/direct_light.glsl"
#include "common/emitter_lookup.glsl"

// A direction about `n` with density cos / pi.
vec3 cosineDirection(vec3 n, float u1, float u2) {
    float r = sqrt(u1), phi = 2.0 * PI * u2;
    vec3 t = abs(n.x) > 0.5 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 b1 = normalize(cross(n, t));
    vec3 b2 = cross(n, b1);
    return normalize(b1 * (r * cos(phi)) + b2 * (r * sin(phi)) + n * sqrt(max(0.0, 1.0 - u1)));
}

// The surface a ray hit, as surfaceFrom reads it from the G-buffer.
Surface surfaceAt(SceneHit hit, vec3 origin, vec3 dir) {
    Surface s;
    s.face = hit.face;
    s.valid = hit.face < 6u;
    s.position = origin + dir * hit.t;
    s.normal = s.valid ? faceNormalF(hit.face) : vec3(0.0);
    s.albedo = materialAlbedo(hit.material);
    s.emission = materialEmission(hit.material);
    return s;
}

// Adds to `L` the light reflected at `s`, vertex number `vertex` of a path (0: the surface the
// camera sees), reached with `throughput`, times that throughput; not s's own emission. (Adding
// into the caller's sum keeps the reference's additions in their old order: its images stayed
// bit-identical when this walk moved here.) At every vertex,
// next-event estimation of the emitters and the sun, and a cosine-weighted ray that counts the
// emission of the light it hits (also from the last vertex, `bounces`, where it goes no further);
// with `mis` the two ways of reaching an emitter are combined by the power heuristic (Veach &
// Guibas 1995), else only light sampling counts and the last vertex traces no ray. Continuation
// rays that escape see the sky; Russian roulette from the third bounce on.
void addPathRadiance(inout vec3 L, Surface s, vec3 throughput, uint vertex, uint bounces, bool mis, bool brickLights,
                     FrameParams frame, inout uint rng) {
    for (uint bounce = vertex; s.valid; ++bounce) {
        bool last = bounce >= bounces;
        if (!mis) {
            L += throughput * directLight(s, frame, rng);
            if (last) break;
        } else {
            L += throughput * directLightMis(s, frame, rng);
        }
        // The cosine-sampled ray: the next vertex and, with MIS, the emitter it hits. From
        // the last vertex it only looks for emitters (the second technique for the light
        // sampled there) and sees no sky, as before MIS.
        vec3 dir = cosineDirection(s.normal, rngNext(rng), rngNext(rng));
        vec3 from = s.position, fromNormal = s.normal;
        throughput *= s.albedo;  // cosine sampling of a diffuse BRDF: f cos / p = albedo
        if (bounce >= 3u) {
            float keep = min(max(throughput.r, max(throughput.g, throughput.b)), 0.95);
            if (rngNext(rng) >= keep) break;
            throughput /= keep;
        }
        vec3 origin = s.position + s.normal * kRayOffset;
        SceneHit hit = traceScene(origin, dir, 1.0e30);
        if (!hit.hit) {
            if (!last) L += throughput * skyBackground(frame, dir);
            break;
        }
        s = surfaceAt(hit, origin, dir);
        // Emission found by the cosine ray, weighted against the light sample that could
        // have found it. Only the lights of the emitter list count (an object's emissive
        // voxel lights nothing, in every method).
        EmitterShape shape;
        if (mis && !hit.dynamicSet && s.valid && emitterOfStaticVoxel(hit.voxel, brickLights, shape) &&
            (shape.emitter.info.x & (1u << hit.face)) != 0u) {
            // Both weights from the same segment (vertex to light point) as directLightMis
            // measures it, so the two weights of every path sum to one.
            vec3 segment = s.position - from;
            float dist = length(segment);
            vec3 toLight = segment / dist;
            float lightPdf = lightSamplePdfSolidAngle(shape, hit.face, from, dist, toLight);
            float bsdfPdf = max(dot(fromNormal, toLight), 0.0) / PI;
            L += throughput * s.emission * powerHeuristic(bsdfPdf, lightPdf);
        }
        if (last) break;
    }
}

#endif
