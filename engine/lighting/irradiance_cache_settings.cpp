#include "lighting/irradiance_cache_settings.h"

#include <fmt/format.h>

namespace engine::lighting {

const char* indirectName(Indirect i) {
    switch (i) {
        case Indirect::None: return "none";
        case Indirect::Cache: return "cache";
        case Indirect::Reference: return "reference";
    }
    return "?";
}

Result<Indirect> parseIndirect(std::string_view name) {
    for (Indirect i : {Indirect::None, Indirect::Cache, Indirect::Reference}) {
        if (name == indirectName(i)) return i;
    }
    return makeError("unknown indirect mode '{}' (known: none, cache, reference)", name);
}

Status validate(const IrradianceCacheSettings& s) {
    if (s.directions < 16 || s.directions > 256) return makeError("directions must be in 16..256, not {}", s.directions);
    if (s.raysPerUpdate < 1 || s.directions % s.raysPerUpdate != 0)
        return makeError("rays ({}) must divide directions ({})", s.raysPerUpdate, s.directions);
    if (s.bounces < 1 || s.bounces > 8) return makeError("bounces must be in 1..8, not {}", s.bounces);
    if (!(s.alpha > 0.0f && s.alpha <= 1.0f)) return makeError("alpha must be in (0, 1], not {}", s.alpha);
    if (s.neighbourhood != 0 && s.neighbourhood != 3 && s.neighbourhood != 5)
        return makeError("neighbourhood must be 0, 3 or 5, not {}", s.neighbourhood);
    if (!(s.maxRayLength >= 1.0f && s.maxRayLength <= 500.0f))
        return makeError("max_ray must be in 1..500 voxels, not {}", s.maxRayLength);
    if (!(s.fadeSeconds > 0.0f)) return makeError("fade must be positive");
    if (s.budgetBytes < (1ull << 20) || s.budgetBytes > (16ull << 30)) return makeError("budget_mb must be in 1..16384");
    return {};
}

std::string IrradianceCacheSettings::describe() const {
    return fmt::format("cache K={} S={} bounces={} alpha={:g} N={} {}", directions, raysPerUpdate, bounces, alpha,
                       neighbourhood, filter ? "filtered" : "unfiltered");
}

}  // namespace engine::lighting
