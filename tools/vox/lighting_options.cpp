#include "lighting_options.h"

#include <algorithm>
#include <cstdio>

namespace vox {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

void addLightingOptions(CLI::App& cmd, LightingOptions& o) {
    cmd.add_option("--method", o.method,
                   "Lighting: restir | restir-unbiased | ris | uniform | bruteforce | reference | preview")
        ->capture_default_str();
    cmd.add_option("--mode", o.mode, "Emitters as point or area lights")->capture_default_str();
    cmd.add_option("--sampling", o.sampling, "Candidate emitters: uniform or by power (alias table)")->capture_default_str();
    cmd.add_option("--candidates", o.candidates, "ReSTIR/RIS candidates per pixel (M)")->capture_default_str();
    cmd.add_option("--brick-lights", o.brickLights, "Uniform emissive bricks as one light: on|off")->capture_default_str();
    cmd.add_option("--spatial", o.spatial, "Spatial reuse taps,radius (0 = off)")->capture_default_str();
    cmd.add_option("--temporal", o.temporal, "Temporal reuse: on|off")->capture_default_str();
    cmd.add_option("--shadow-rays", o.shadowRays, "uniform: light samples (and shadow rays) per pixel")->capture_default_str();
    cmd.add_option("--bounces", o.bounces, "reference: indirect bounces (0 = direct light only)")->capture_default_str();
    cmd.add_option("--pixel-filter", o.pixelFilter,
                   "reference: box (jittered over the pixel) | centre (one ray through the pixel centre, the pixel "
                   "the other methods shade)")
        ->capture_default_str();
    cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str();
    cmd.add_option("--indirect", o.indirect,
                   "Indirect light: none | cache (voxel-face irradiance cache) | reference (path-traced bounces); "
                   "default: the scene's [indirect] mode, else none");
    cmd.add_option("--cache-directions", o.cacheDirections, "cache: K directions per voxel face, 16..256 (128)");
    cmd.add_option("--cache-rays", o.cacheRays, "cache: of the K, rays per face per frame, a divisor of K (16)");
    cmd.add_option("--cache-bounces", o.cacheBounces, "cache: 1 = one bounce (the paper); more reads the cache at each hit (1)");
    cmd.add_option("--cache-alpha", o.cacheAlpha, "cache: temporal blend factor (0.03)");
    cmd.add_option("--cache-neighbourhood", o.cacheNeighbourhood, "cache: N^3 around visible dynamic voxels: 0, 3, 5 (5)");
    cmd.add_option("--cache-max-ray", o.cacheMaxRay, "cache: ray length in voxels, also an edit's reach, up to 500 (500)");
    cmd.add_option("--cache-filter", o.cacheFilter, "cache: 3^3 filter on|off (on)");
    cmd.add_option("--cache-budget-mb", o.cacheBudgetMb, "cache: memory budget in MiB; least recently seen evicted (64)");
}

engine::Result<LightingSettings> lightingSettings(const LightingOptions& o, const engine::world::Scene* scene) {
    LightingSettings s;
    std::string method = o.method;
    if (method == "restir-unbiased") {
        method = "restir";
        s.unbiased = true;
    }
    auto m = engine::lighting::parseMethod(method);
    if (!m) return engine::makeError("--method: {}", m.error().message);
    s.method = *m;
    auto onOff = [](const std::string& v, const char* option) -> engine::Result<bool> {
        if (v == "on") return true;
        if (v == "off") return false;
        return engine::makeError("{}: expected on or off, got '{}'", option, v);
    };
    if (o.mode != "area" && o.mode != "point") return engine::makeError("--mode: expected point or area, got '{}'", o.mode);
    s.area = o.mode == "area";
    if (o.sampling != "power" && o.sampling != "uniform")
        return engine::makeError("--sampling: expected uniform or power, got '{}'", o.sampling);
    s.byPower = o.sampling == "power";
    if (o.candidates < 1 || o.candidates > 1024) return engine::makeError("--candidates must be in 1..1024");
    s.candidates = o.candidates;
    auto brick = onOff(o.brickLights, "--brick-lights");
    if (!brick) return brick.error();
    s.brickLights = *brick;
    auto temporal = onOff(o.temporal, "--temporal");
    if (!temporal) return temporal.error();
    s.temporal = *temporal;
    unsigned taps = 0;
    float radius = 0.0f;
    char extra = 0;
    if (o.spatial == "0" || o.spatial == "off") {
        s.spatial = false;
    } else if (std::sscanf(o.spatial.c_str(), "%u,%f%c", &taps, &radius, &extra) == 2 && taps <= 16 && radius > 0.0f &&
               radius <= 256.0f) {
        s.spatial = taps > 0;
        s.spatialTaps = taps;
        s.spatialRadius = radius;
    } else {
        return engine::makeError("--spatial: expected TAPS,RADIUS with taps in 0..16 and radius in (0, 256], or 0");
    }
    if (s.method == Method::Ris) {
        s.temporal = false;
        s.spatial = false;
        s.candidateVisibility = false;
    }
    if (o.shadowRays < 1 || o.shadowRays > 4096) return engine::makeError("--shadow-rays must be in 1..4096");
    s.shadowRays = o.shadowRays;
    if (o.bounces > 64) return engine::makeError("--bounces must be in 0..64");
    s.bounces = o.bounces;
    if (o.pixelFilter != "box" && o.pixelFilter != "centre")
        return engine::makeError("--pixel-filter: expected box or centre, got '{}'", o.pixelFilter);
    s.referenceFilter = o.pixelFilter == "box" ? engine::lighting::ReferenceFilter::Box
                                               : engine::lighting::ReferenceFilter::PixelCentre;
    s.seed = o.seed;

    s.indirect = scene ? scene->indirect : engine::lighting::Indirect::None;
    if (o.indirect) {
        auto indirect = engine::lighting::parseIndirect(*o.indirect);
        if (!indirect) return engine::makeError("--indirect: {}", indirect.error().message);
        s.indirect = *indirect;
    }
    if (s.indirect == engine::lighting::Indirect::Reference) {
        // The path tracer with bounces is the indirect reference; it replaces the direct method.
        s.method = Method::Reference;
        s.bounces = std::max(s.bounces, 1u);
    }
    auto& c = s.cache;
    if (scene) c = scene->cache;
    c.directions = o.cacheDirections.value_or(c.directions);
    c.raysPerUpdate = o.cacheRays.value_or(c.raysPerUpdate);
    c.bounces = o.cacheBounces.value_or(c.bounces);
    c.alpha = o.cacheAlpha.value_or(c.alpha);
    c.neighbourhood = o.cacheNeighbourhood.value_or(c.neighbourhood);
    c.maxRayLength = o.cacheMaxRay.value_or(c.maxRayLength);
    if (o.cacheBudgetMb) {
        if (!(*o.cacheBudgetMb >= 1.0 && *o.cacheBudgetMb <= 16384.0)) return engine::makeError("--cache-budget-mb must be in 1..16384");
        c.budgetBytes = static_cast<std::uint64_t>(*o.cacheBudgetMb * 1048576.0);
    }
    if (o.cacheFilter) {
        auto filter = onOff(*o.cacheFilter, "--cache-filter");
        if (!filter) return filter.error();
        c.filter = *filter;
    }
    if (engine::Status valid = engine::lighting::validate(c); !valid) return engine::makeError("cache: {}", valid.error().message);
    return s;
}

}  // namespace vox
