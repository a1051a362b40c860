// The [indirect] keys of scene/indirect_keys.h.
#include "scene/indirect_keys.h"

namespace engine::scene {

void readIndirect(KeyReader& ind, const toml::node& table, world::Scene& scene) {
    if (const toml::node* mode = ind.node("mode")) {
        auto name = mode->value<std::string>();
        auto parsed = lighting::parseIndirect(name ? *name : "");
        if (!parsed) ind.fail(mode, "indirect: {}", parsed.error().message);
        scene.indirect = *parsed;
    }
    lighting::IrradianceCacheSettings& c = scene.cache;
    auto count = [&](std::string_view key, std::uint32_t fallback) {
        int v = ind.integer(key, static_cast<int>(fallback));
        if (v < 0) ind.fail(ind.node(key), "'{}' must not be negative", key);
        return static_cast<std::uint32_t>(v);
    };
    c.directions = count("directions", c.directions);
    c.raysPerUpdate = count("rays", c.raysPerUpdate);
    c.bounces = count("bounces", c.bounces);
    c.neighbourhood = count("neighbourhood", c.neighbourhood);
    c.alpha = static_cast<float>(ind.number("alpha", c.alpha));
    c.fadeSeconds = static_cast<float>(ind.number("fade", c.fadeSeconds));
    c.maxRayLength = static_cast<float>(ind.number("max_ray", c.maxRayLength));
    c.filter = ind.boolean("filter", c.filter);
    c.budgetBytes = static_cast<std::uint64_t>(
        ind.number("budget_mb", double(c.budgetBytes) / 1048576.0) * 1048576.0);
    if (Status s = lighting::validate(c); !s) ind.fail(&table, "indirect: {}", s.error().message);
}

void writeIndirect(const world::Scene& scene, TomlWriter& out) {
    const world::Scene defaults;
    const lighting::IrradianceCacheSettings& c = scene.cache;
    const lighting::IrradianceCacheSettings& d = defaults.cache;
    if (scene.indirect == defaults.indirect && c == d) return;
    out.table("indirect");
    if (scene.indirect != defaults.indirect)
        out.key("mode", lighting::indirectName(scene.indirect));
    if (c.directions != d.directions) out.key("directions", c.directions);
    if (c.raysPerUpdate != d.raysPerUpdate) out.key("rays", c.raysPerUpdate);
    if (c.bounces != d.bounces) out.key("bounces", c.bounces);
    if (c.alpha != d.alpha) out.key("alpha", c.alpha);
    if (c.fadeSeconds != d.fadeSeconds) out.key("fade", c.fadeSeconds);
    if (c.neighbourhood != d.neighbourhood) out.key("neighbourhood", c.neighbourhood);
    if (c.maxRayLength != d.maxRayLength) out.key("max_ray", c.maxRayLength);
    if (c.filter != d.filter) out.key("filter", c.filter);
    // Bytes / 2^20 is exact in a double, and reads back to the same bytes.
    if (c.budgetBytes != d.budgetBytes) out.key("budget_mb", double(c.budgetBytes) / 1048576.0);
}

}  // namespace engine::scene
