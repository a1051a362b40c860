// Knobs of the voxel-face irradiance cache (Cosin Ayerbe et al. §4), shared by the renderer, the
// command line and scene files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"

namespace engine::lighting {

enum class Indirect {
    None,   // direct light only
    Cache,  // the voxel-face irradiance cache
    // Path-traced bounces from the G-buffer's surfaces added to the direct method, accumulated
    // while camera and world stay still (render/path_indirect/)
    Path,
    Reference,  // the path tracer's bounces (the method becomes the reference)
    // Voxel cone tracing: a radiance clipmap injected from direct light, six cones per pixel
    // (render/vct/); cheap and leaky
    Vct,
};

struct IrradianceCacheSettings {
    std::uint32_t directions = 128;  // K fixed jittered directions per face (16..256)
    std::uint32_t raysPerUpdate =
        16;  // of the K, traced per face per frame (a divisor of K); all K in K/S frames
    std::uint32_t bounces = 1;  // 1 = the paper; more reads the cached irradiance at each ray's hit
    float alpha = 0.03f;        // temporal blend E = a E_new + (1 - a) E_old
    float fadeSeconds = 0.3f;   // dynamic entries fade to zero this long after their last update
    // N^3 around each visible dynamic voxel (0, 3 or 5): entries ready where a moving object is
    // about to be. 3 (the paper's) covers a voxel a frame; 5 cost the sandbox's rolling cart 2.8x
    // the dynamic updates for a small gain (docs/STABILITY.md).
    std::uint32_t neighbourhood = 3;
    // Voxels (at most 500, shared::CACHE_MAX_RAY_LENGTH); also the reach of an edit's invalidation.
    // A ray cut short sees the sky, so it must cross the largest room: cornell needs 443.
    float maxRayLength = 500.0f;
    bool filter = true;  // 3^3 Gaussian over neighbouring voxels' faces
    // Slots beyond it evict the least recently seen. Buffers grow with the entries, so an unused
    // budget costs nothing; 256 MiB holds a flythrough's entries long enough to converge (64 MiB
    // evicted the Cornell box's: twice the error on a moving camera, docs/history/ACCURACY.md).
    std::uint64_t budgetBytes = 256ull << 20;
    // Rays per frame the cache's updates may trace, spent by priority (new and edited entries,
    // moving objects, changed light, then the most stale); 0: update every visible entry each
    // frame. 100 000 keeps the sandbox's full frame near 10 fps on two cores at converged errors
    // within 4 % of 150 000's (docs/ACCURACY.md).
    std::uint32_t rayBudget = 100000;
    // Static faces at least this far along the view ray (voxels) share a coarse entry per open,
    // coplanar 2x2 patch (render/irradiance_cache/cache_lod.h); 0: every voxel its own entry.
    // A quarter of the entries far away, each updated more often: lower error on a moving camera.
    float lodDistance = 32.0f;
    // A pixel whose voxel has no entry yet (first seen this frame, or waiting for the ray budget)
    // reads the nearest entries of the same face within this many voxels in the face's plane,
    // reachable through the open space in front of it (never across a wall); 0: it reads nothing.
    std::uint32_t fallbackRadius = 4;
    // Of an update's hits per face that can receive light, how many sample the direct light there
    // (sun and one emitter, one shadow ray for the two), a stratified subset weighted to stay
    // unbiased; 0: every one. The shadow rays are most of the bounce's cost; 8 makes cache.bounce
    // ~0.6x as dear but its MAE +8 % on the Cornell box (+12 % against the unbudgeted cache), so 0
    // stays the default (docs/ACCURACY.md).
    std::uint32_t lightSamples = 0;
    bool fullRetrace = false;  // tests: every entry traces the whole world every update

    bool operator==(const IrradianceCacheSettings&) const = default;
};

const char* indirectName(Indirect i);
Result<Indirect> parseIndirect(std::string_view name);

}  // namespace engine::lighting
