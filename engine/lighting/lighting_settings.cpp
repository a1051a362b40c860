#include "lighting/lighting_settings.h"

#include <fmt/format.h>

namespace engine::lighting {

const char* methodName(Method m) {
    switch (m) {
        case Method::Preview:
            return "preview";
        case Method::Restir:
            return "restir";
        case Method::Ris:
            return "ris";
        case Method::Uniform:
            return "uniform";
        case Method::BruteForce:
            return "bruteforce";
        case Method::Reference:
            return "reference";
    }
    return "?";
}

Result<Method> parseMethod(std::string_view name) {
    for (Method m : {Method::Preview, Method::Restir, Method::Ris, Method::Uniform,
                     Method::BruteForce, Method::Reference}) {
        if (name == methodName(m)) return m;
    }
    return makeError(
        "unknown lighting method '{}' (known: preview, restir, restir-unbiased, ris, uniform, "
        "bruteforce, reference)",
        name);
}

bool resamples(const LightingSettings& s) {
    return s.method == Method::Restir || s.method == Method::Ris;
}
bool samplesLightsPerPixel(const LightingSettings& s) {
    return s.method == Method::Uniform || s.method == Method::BruteForce;
}
bool usesCache(const LightingSettings& s) {
    return s.indirect == Indirect::Cache && s.method != Method::Reference;
}
bool usesPath(const LightingSettings& s) {
    return s.indirect == Indirect::Path && s.method != Method::Reference;
}
bool usesVct(const LightingSettings& s) {
    return s.indirect == Indirect::Vct && s.method != Method::Reference;
}
bool usesAutoExposure(const LightingSettings& s) { return s.exposure.automatic; }
bool reconstructs(const LightingSettings& s) {
    return s.display.mode != Display::Raw && s.method != Method::Reference;
}
bool denoises(const LightingSettings& s) {
    return s.display.mode == Display::Denoised && reconstructs(s) && s.method != Method::Preview;
}
bool accumulates(const LightingSettings& s) {
    return s.accumulation.enabled && s.method != Method::Reference && s.method != Method::Preview;
}
bool usesRegir(const LightingSettings& s) { return s.regir.enabled != 0u && resamples(s); }
bool mayUseRegir(const LightingSettings& s) {
    return usesRegir(s) || (s.autoSampling && s.byPower && resamples(s));
}
bool drawsLightsByPower(const LightingSettings& s) {
    return s.byPower && (resamples(s) || usesCache(s));
}
bool usesLightTiles(const LightingSettings& s) {
    return s.restir.lightTiles != 0u && drawsLightsByPower(s);
}
bool usesSkyTerm(const LightingSettings& s) {
    return s.sky != Sky::None && s.method != Method::Preview && s.method != Method::Reference &&
           s.indirect == Indirect::None;
}

}  // namespace engine::lighting
