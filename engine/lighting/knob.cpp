#include "lighting/knob.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "core/number_check.h"
#include "lighting/lighting_settings.h"

namespace engine::lighting {
namespace {

std::string choiceList(const Knob& knob) {
    std::string list;
    for (std::string_view c : knob.choices)
        list += fmt::format("{}{}", list.empty() ? "" : ", ", c);
    return list;
}

Status inRange(const Knob& knob, double v) { return checkNumber(knob.name, v, knobRange(knob)); }

}  // namespace

Status setKnob(const Knob& knob, LightingSettings& s, std::string_view text) {
    switch (knob.kind) {
        case KnobKind::Count:
        case KnobKind::Real: {
            auto v = readNumber(text);
            if (!v) return makeError("{}: expected a number, got '{}'", knob.name, text);
            if (Status ok = inRange(knob, *v); !ok) return ok;
            knob.set(s, *v);
            return {};
        }
        case KnobKind::Switch:
            if (text == "on" || text == "true")
                knob.set(s, 1.0);
            else if (text == "off" || text == "false")
                knob.set(s, 0.0);
            else
                return makeError("{}: expected on or off, got '{}'", knob.name, text);
            return {};
        case KnobKind::Choice:
            for (std::size_t i = 0; i < knob.choices.size(); ++i) {
                if (text == knob.choices[i]) {
                    knob.set(s, static_cast<double>(i));
                    return {};
                }
            }
            return makeError("{}: unknown value '{}' (known: {})", knob.name, text,
                             choiceList(knob));
        case KnobKind::Custom:
            return knob.parse(s, text);
    }
    return makeError("{}: unknown knob kind", knob.name);
}

std::string knobText(const Knob& knob, const LightingSettings& s) {
    switch (knob.kind) {
        case KnobKind::Count:
            return fmt::format("{}", static_cast<long long>(knob.get(s)));
        case KnobKind::Real:
            return fmt::format("{}", static_cast<float>(knob.get(s)));
        case KnobKind::Switch:
            return knob.get(s) != 0.0 ? "on" : "off";
        case KnobKind::Choice: {
            auto i = static_cast<std::size_t>(knob.get(s));
            return i < knob.choices.size() ? std::string(knob.choices[i]) : "?";
        }
        case KnobKind::Custom:
            return knob.format(s);
    }
    return "?";
}

Status checkKnob(const Knob& knob, const LightingSettings& s) {
    switch (knob.kind) {
        case KnobKind::Count:
        case KnobKind::Real:
            return inRange(knob, knob.get(s));
        case KnobKind::Switch:
            return {};
        case KnobKind::Choice:
            if (knob.get(s) >= 0.0 && knob.get(s) < static_cast<double>(knob.choices.size()))
                return {};
            return makeError("{}: value {} is not one of {}", knob.name, knob.get(s),
                             choiceList(knob));
        case KnobKind::Custom:
            return knob.check ? knob.check(s) : Status{};
    }
    return {};
}

NumberRange knobRange(const Knob& knob) {
    return knob.kind == KnobKind::Count ? wholeRange(knob.min, knob.max)
                                        : closedRange(knob.min, knob.max);
}

bool knobRelevant(const Knob& knob, const LightingSettings& s) {
    return !knob.relevant || knob.relevant(s);
}

}  // namespace engine::lighting
