// Knobs: every lighting setting described once — its name, range, help and where it lives in
// LightingSettings — so the command line, scene files, the HUD and validation read one
// description instead of each keeping its own defaults and limits. The defaults are the member
// initialisers of LightingSettings; the tables are in lighting/lighting_knobs.h.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/number_check.h"

namespace engine::lighting {

struct LightingSettings;

enum class KnobKind {
    Count,   // whole number in [min, max]
    Real,    // number in [min, max]
    Switch,  // on/off (scene files: true/false)
    Choice,  // one of `choices`; the value is its index
    Custom,  // its own text form (parse/format/check)
};

struct Knob {
    std::string_view
        name;  // scene-file key; the command line spells it --PREFIX-NAME with '-' for '_'
    std::string_view help;
    KnobKind kind = KnobKind::Count;
    double min = 0.0, max = 0.0;
    std::span<const std::string_view> choices;
    double (*get)(const LightingSettings&) = nullptr;
    void (*set)(LightingSettings&, double) = nullptr;
    // Whether the knob matters for these settings (the HUD hides it otherwise); null: always.
    bool (*relevant)(const LightingSettings&) = nullptr;
    // Custom kind only.
    Status (*parse)(LightingSettings&, std::string_view) = nullptr;
    std::string (*format)(const LightingSettings&) = nullptr;
    Status (*check)(const LightingSettings&) = nullptr;
};

// Reads `text` as the command line and scene files write it: a number, on/off (or true/false),
// a choice's name. Refuses values outside the knob's range; the message names the knob.
Status setKnob(const Knob& knob, LightingSettings& s, std::string_view text);
// The value in the form setKnob reads.
std::string knobText(const Knob& knob, const LightingSettings& s);
// Whether the current value is in range (for settings built in code: benches, the HUD).
Status checkKnob(const Knob& knob, const LightingSettings& s);
bool knobRelevant(const Knob& knob, const LightingSettings& s);
// The range of a Count or Real knob for the one number check (core/number_check.h); the command
// line's check of --PREFIX-NAME is built from it too.
NumberRange knobRange(const Knob& knob);

}  // namespace engine::lighting
