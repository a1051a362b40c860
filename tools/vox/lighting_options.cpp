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
    cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str();
    cmd.add_option("--indirect", o.indirect,
                   "Indirect light: none | cache (voxel-face irradiance cache) | reference (path-traced bounces)")
        ->capture_default_str();
    cmd.add_option("--cache-directions", o.cacheDirections, "cache: K directions per voxel face (16..256)")->capture_default_str();
    cmd.add_option("--cache-rays", o.cacheRays, "cache: of the K, rays per face per frame (a divisor of K)")->capture_default_str();
    cmd.add_option("--cache-bounces", o.cacheBounces, "cache: 1 = one bounce (the paper); more reads the cache at each hit")
        ->capture_default_str();
    cmd.add_option("--cache-alpha", o.cacheAlpha, "cache: temporal blend factor")->capture_default_str();
    cmd.add_option("--cache-neighbourhood", o.cacheNeighbourhood, "cache: N^3 around visible dynamic voxels (0, 3, 5)")
        ->capture_default_str();
    cmd.add_option("--cache-max-ray", o.cacheMaxRay, "cache: ray length in voxels (also an edit's reach), up to 250")
        ->capture_default_str();
    cmd.add_option("--cache-filter", o.cacheFilter, "cache: 3^3 filter on|off")->capture_default_str();
    cmd.add_option("--cache-budget-mb", o.cacheBudgetMb, "cache: memory budget in MiB (least recently seen evicted)")
        ->capture_default_str();
}

engine::Result<LightingSettings> lightingSettings(const LightingOptions& o) {
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
    s.seed = o.seed;

    if (o.indirect == "none") {
        s.indirect = engine::lighting::Indirect::None;
    } else if (o.indirect == "cache") {
        s.indirect = engine::lighting::Indirect::Cache;
    } else if (o.indirect == "reference") {
        // The path tracer with bounces is the indirect reference; it replaces the direct method.
        s.indirect = engine::lighting::Indirect::Reference;
        s.method = Method::Reference;
        s.bounces = std::max(s.bounces, 1u);
    } else {
        return engine::makeError("--indirect: expected none, cache or reference, got '{}'", o.indirect);
    }
    auto& c = s.cache;
    if (o.cacheDirections < 16 || o.cacheDirections > 256) return engine::makeError("--cache-directions must be in 16..256");
    if (o.cacheRays < 1 || o.cacheRays > o.cacheDirections || o.cacheDirections % o.cacheRays != 0)
        return engine::makeError("--cache-rays must divide --cache-directions ({})", o.cacheDirections);
    if (o.cacheBounces < 1 || o.cacheBounces > 8) return engine::makeError("--cache-bounces must be in 1..8");
    if (!(o.cacheAlpha > 0.0f && o.cacheAlpha <= 1.0f)) return engine::makeError("--cache-alpha must be in (0, 1]");
    if (o.cacheNeighbourhood != 0 && o.cacheNeighbourhood != 3 && o.cacheNeighbourhood != 5)
        return engine::makeError("--cache-neighbourhood must be 0, 3 or 5");
    if (!(o.cacheMaxRay >= 1.0f && o.cacheMaxRay <= 250.0f)) return engine::makeError("--cache-max-ray must be in 1..250");
    if (!(o.cacheBudgetMb >= 1.0 && o.cacheBudgetMb <= 16384.0)) return engine::makeError("--cache-budget-mb must be in 1..16384");
    auto filter = onOff(o.cacheFilter, "--cache-filter");
    if (!filter) return filter.error();
    c.directions = o.cacheDirections;
    c.raysPerUpdate = o.cacheRays;
    c.bounces = o.cacheBounces;
    c.alpha = o.cacheAlpha;
    c.neighbourhood = o.cacheNeighbourhood;
    c.maxRayLength = o.cacheMaxRay;
    c.filter = *filter;
    c.budgetBytes = static_cast<std::uint64_t>(o.cacheBudgetMb * 1024.0 * 1024.0);
    return s;
}

}  // namespace vox
