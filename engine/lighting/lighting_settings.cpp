#include "lighting/lighting_settings.h"

#include <fmt/format.h>

namespace engine::lighting {

const char* methodName(Method m) {
    switch (m) {
        case Method::Preview: return "preview";
        case Method::Restir: return "restir";
        case Method::Ris: return "ris";
        case Method::Uniform: return "uniform";
        case Method::BruteForce: return "bruteforce";
        case Method::Reference: return "reference";
    }
    return "?";
}

Result<Method> parseMethod(std::string_view name) {
    for (Method m : {Method::Preview, Method::Restir, Method::Ris, Method::Uniform, Method::BruteForce, Method::Reference}) {
        if (name == methodName(m)) return m;
    }
    return makeError("unknown lighting method '{}' (known: preview, restir, restir-unbiased, ris, uniform, bruteforce, reference)",
                     name);
}

std::string LightingSettings::describe() const {
    std::string s = methodName(method);
    switch (method) {
        case Method::Restir:
            s += fmt::format(" {} {} M={} {} {}{}{}", restir.unbiased ? "unbiased" : "biased", area ? "area" : "point",
                             restir.candidates,
                             regir.enabled ? "regir" : byPower ? "power" : "uniform", brickLights ? "bricks" : "voxels",
                             restir.temporal ? " temporal" : "",
                             restir.spatial ? fmt::format(" spatial {}x{:.0f}px", restir.spatialTaps, restir.spatialRadius) : "");
            break;
        case Method::Ris:
            s += fmt::format(" {} M={} {} {}", area ? "area" : "point", restir.candidates,
                             regir.enabled ? "regir" : byPower ? "power" : "uniform",
                             brickLights ? "bricks" : "voxels");
            break;
        case Method::Uniform:
            s += fmt::format(" {} {} rays {} {}", area ? "area" : "point", shadowRays, byPower ? "power" : "uniform",
                             brickLights ? "bricks" : "voxels");
            break;
        case Method::BruteForce: s += area ? " area" : " point"; break;
        case Method::Reference: s += fmt::format(" {} bounce(s)", bounces); break;
        case Method::Preview: break;
    }
    if (indirect == Indirect::Cache && method != Method::Reference) s += " + " + cache.describe();
    if (indirect == Indirect::Path && method != Method::Reference) s += " + " + path.describe();
    if (skyTermUsed()) s += sky == Sky::Dvf ? " + sky dvf" : " + sky reference";
    if (indirect == Indirect::Vct && method != Method::Reference) s += " + " + vct.describe();
    return s;
}

}  // namespace engine::lighting
