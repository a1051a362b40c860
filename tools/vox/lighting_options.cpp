#include "lighting_options.h"

#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "number_options.h"
#include "scene/scene_lighting.h"

namespace vox {

using engine::lighting::KnobGroup;
using engine::lighting::KnobValue;
using engine::lighting::LightingSettings;

namespace {

std::string typeName(const engine::lighting::Knob& k) {
    switch (k.kind) {
        case engine::lighting::KnobKind::Count:
            return "UINT";
        case engine::lighting::KnobKind::Real:
            return "FLOAT";
        case engine::lighting::KnobKind::Switch:
            return "on|off";
        case engine::lighting::KnobKind::Choice:
            break;
        case engine::lighting::KnobKind::Custom:
            return "TEXT";
    }
    std::string names;
    for (std::string_view c : k.choices) names += fmt::format("{}{}", names.empty() ? "" : "|", c);
    return names;
}

}  // namespace

void addLightingOptions(CLI::App& cmd, LightingOptions& o) {
    std::size_t count = 0;
    for (const KnobGroup& g : engine::lighting::knobGroups()) count += g.knobs.size();
    o.given.assign(count, std::nullopt);  // sized once: CLI11 keeps pointers into it
    const LightingSettings defaults;
    std::size_t i = 0;
    for (const KnobGroup& g : engine::lighting::knobGroups()) {
        for (const engine::lighting::Knob& k : g.knobs) {
            std::string help = fmt::format("{} (default: {})", k.help, knobText(k, defaults));
            if (k.kind == engine::lighting::KnobKind::Count ||
                k.kind == engine::lighting::KnobKind::Real)
                help = fmt::format("{}; {}..{}", help, k.min, k.max);
            CLI::Option* option =
                cmd.add_option(knobOption(g, k), o.given[i++], help)->type_name(typeName(k));
            if (k.kind == engine::lighting::KnobKind::Count ||
                k.kind == engine::lighting::KnobKind::Real)
                option->check(numberIn(engine::lighting::knobRange(k)));
        }
    }
    cmd.add_flag("--show-settings", o.showSettings,
                 "Print the lighting settings this command would use, and stop");
}

std::vector<KnobValue> lightingOverrides(const LightingOptions& o) {
    std::vector<KnobValue> out;
    std::size_t i = 0;
    for (const KnobGroup& g : engine::lighting::knobGroups()) {
        for (const engine::lighting::Knob& k : g.knobs) {
            if (i < o.given.size() && o.given[i])
                out.push_back({&k, *o.given[i], knobOption(g, k)});
            ++i;
        }
    }
    return out;
}

engine::Result<LightingSettings> lightingSettings(const LightingOptions& o,
                                                  const engine::world::Scene* scene) {
    return engine::scene::lightingFor(scene, lightingOverrides(o), o.commandDefaults);
}

std::string settingsText(const LightingSettings& s) {
    std::string text;
    for (const KnobGroup& g : engine::lighting::knobGroups()) {
        for (const engine::lighting::Knob& k : g.knobs)
            text += fmt::format("{} {}\n", knobOption(g, k), knobText(k, s));
    }
    return text;
}

int showSettings(const std::string& world, const LightingOptions& options) {
    auto scene = loadWorld(world);
    if (!scene) return fail(scene.error());
    auto settings = lightingSettings(options, &*scene);
    if (!settings) return fail(settings.error());
    std::fputs(settingsText(*settings).c_str(), stdout);
    return 0;
}

engine::Result<std::vector<engine::lighting::KnobValue>> knobValuesOf(const std::string& text,
                                                                      const std::string& where) {
    std::vector<std::string> words;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find(' ', at);
        if (end == std::string::npos) end = text.size();
        if (end > at) words.push_back(text.substr(at, end - at));
        at = end + 1;
    }
    std::vector<engine::lighting::KnobValue> out;
    for (std::size_t i = 0; i < words.size(); i += 2) {
        const std::string& option = words[i];
        const engine::lighting::Knob* k = option.rfind("--", 0) == 0
                                              ? engine::lighting::knobForOption(option.substr(2))
                                              : nullptr;
        if (!k)
            return engine::makeError(
                "{}: '{}' is not a lighting option (vox render --help lists them)", where, option);
        if (i + 1 >= words.size()) return engine::makeError("{}: {} needs a value", where, option);
        out.push_back({k, words[i + 1], fmt::format("{} {}", where, option)});
    }
    return out;
}

}  // namespace vox
