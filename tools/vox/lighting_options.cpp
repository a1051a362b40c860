#include "lighting_options.h"

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
    return s;
}

}  // namespace vox
