// The [indirect] keys of scene/indirect_keys.h: `mode` is the lighting knob `indirect`, every
// other key a knob of the cache's, the path term's or the cones' table (lighting/lighting_knobs.h),
// read and range-checked by that table, so a scene file accepts exactly what the command line
// accepts.
#include "scene/indirect_keys.h"

#include <fmt/format.h>

#include "lighting/lighting_knobs.h"

namespace engine::scene {
namespace {

// A TOML value as the knob's text form.
std::string valueText(const toml::node& n) {
    if (auto s = n.value_exact<std::string>()) return *s;
    if (auto b = n.value_exact<bool>()) return *b ? "on" : "off";
    if (auto i = n.value_exact<std::int64_t>()) return fmt::format("{}", *i);
    if (auto d = n.value_exact<double>()) return fmt::format("{}", *d);
    return "?";
}

}  // namespace

const lighting::Knob* indirectKnob(std::string_view key) {
    if (key == "mode") return lighting::knobForOption("indirect");
    // How a world's lights are sampled is the world's to say too (a world of many lights spread
    // far apart may want regir however auto decides).
    if (key == "sampling") return lighting::knobForOption("sampling");
    for (std::string_view group : {"cache", "path", "vct"}) {
        for (const lighting::Knob& k : lighting::knobGroup(group).knobs) {
            if (k.name == key) return &k;
        }
    }
    return nullptr;
}

void readIndirect(KeyReader& ind, const toml::node& table, world::Scene& scene) {
    lighting::LightingSettings s;
    scene.indirect.clear();
    for (const auto& [key, value] : ind.raw()) {
        const lighting::Knob* knob = indirectKnob(key.str());
        if (!knob) continue;  // KeyReader reports it as unknown
        const toml::node* n = ind.node(key.str());
        if (Status ok = lighting::setKnob(*knob, s, valueText(value)); !ok)
            ind.fail(n, "indirect: {}", ok.error().message);
        scene.indirect.emplace_back(std::string(key.str()), knobText(*knob, s));
    }
    if (Status ok = lighting::validate(s); !ok)
        ind.fail(&table, "indirect: {}", ok.error().message);
}

void writeIndirect(const world::Scene& scene, TomlWriter& out) {
    if (scene.indirect.empty()) return;
    out.table("indirect");
    for (const auto& [key, text] : scene.indirect) {
        const lighting::Knob* k = indirectKnob(key);
        lighting::LightingSettings s;
        if (!k || !setKnob(*k, s, text).ok()) continue;  // not from readIndirect: nothing to write
        const double v = k->get ? k->get(s) : 0.0;
        switch (k->kind) {
            case lighting::KnobKind::Count:
                out.key(key, static_cast<std::uint32_t>(v));
                break;
            // In the shortest form that reads back exactly: a float's, or a double's for a value
            // no float holds (a budget in bytes that is no whole MiB).
            case lighting::KnobKind::Real:
                if (static_cast<double>(static_cast<float>(v)) == v)
                    out.key(key, static_cast<float>(v));
                else
                    out.key(key, v);
                break;
            case lighting::KnobKind::Switch:
                out.key(key, v != 0.0);
                break;
            default:
                out.key(key, text);
                break;
        }
    }
}

}  // namespace engine::scene
