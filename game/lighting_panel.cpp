#include "game/lighting_panel.h"

#include <algorithm>
#include <cstring>
#include <imgui.h>

#include "lighting/lighting_knobs.h"

namespace game {
namespace {

using engine::lighting::Knob;
using engine::lighting::KnobKind;
using engine::lighting::LightingSettings;

// A range spanning orders of magnitude gets a logarithmic slider.
ImGuiSliderFlags sliderFlags(const Knob& k) {
    return k.min > 0.0 && k.max / k.min > 100.0 ? ImGuiSliderFlags_Logarithmic
                                                : ImGuiSliderFlags_None;
}

bool drawChoice(const Knob& k, LightingSettings& s) {
    std::string current = knobText(k, s);
    bool changed = false;
    if (ImGui::BeginCombo(k.name.data(), current.c_str())) {
        for (std::string_view c : k.choices) {
            std::string name(c);
            if (ImGui::Selectable(name.c_str(), name == current))
                changed = setKnob(k, s, name).ok();
        }
        ImGui::EndCombo();
    }
    return changed;
}

// A number from a slider (Ctrl+click types any text, NaN and out-of-range values included) goes
// through the knob's own range check (the one number check) before it is taken.
bool setChecked(const Knob& k, LightingSettings& s, double v) {
    LightingSettings t = s;
    k.set(t, v);
    if (!checkKnob(k, t).ok()) return false;
    s = t;
    return true;
}

bool drawWidget(const Knob& k, LightingSettings& s) {
    switch (k.kind) {
        case KnobKind::Count: {
            if (k.max > 1e6) {  // the seed: typed, not slid
                int v = static_cast<int>(k.get(s));
                if (!ImGui::InputInt(k.name.data(), &v)) return false;
                k.set(s, std::clamp(static_cast<double>(v), k.min, k.max));
                return true;
            }
            int v = static_cast<int>(k.get(s));
            if (!ImGui::SliderInt(k.name.data(), &v, static_cast<int>(k.min),
                                  static_cast<int>(k.max), "%d", sliderFlags(k)))
                return false;
            return setChecked(k, s, v);
        }
        case KnobKind::Real: {
            float v = static_cast<float>(k.get(s));
            if (!ImGui::SliderFloat(k.name.data(), &v, static_cast<float>(k.min),
                                    static_cast<float>(k.max), "%.3g", sliderFlags(k)))
                return false;
            return setChecked(k, s, v);
        }
        case KnobKind::Switch: {
            bool v = k.get(s) != 0.0;
            if (!ImGui::Checkbox(k.name.data(), &v)) return false;
            k.set(s, v ? 1.0 : 0.0);
            return true;
        }
        case KnobKind::Choice:
            return drawChoice(k, s);
        case KnobKind::Custom: {
            if (!k.choices.empty()) return drawChoice(k, s);
            char text[64];
            std::string current = knobText(k, s);
            std::strncpy(text, current.c_str(), sizeof text - 1);
            text[sizeof text - 1] = 0;
            if (!ImGui::InputText(k.name.data(), text, sizeof text,
                                  ImGuiInputTextFlags_EnterReturnsTrue))
                return false;
            return setKnob(k, s, text).ok();
        }
    }
    return false;
}

bool drawKnob(const Knob& k, LightingSettings& s) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    bool changed = drawWidget(k, s);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%.*s", static_cast<int>(k.help.size()), k.help.data());
    return changed;
}

}  // namespace

bool LightingPanel::draw(LightingSettings& settings, float width) {
    LightingSettings edited = settings;
    bool changed = false;
    for (const engine::lighting::KnobGroup& g : engine::lighting::knobGroups()) {
        bool any = std::any_of(g.knobs.begin(), g.knobs.end(),
                               [&](const Knob& k) { return knobRelevant(k, edited); });
        if (!any) continue;
        bool open = g.name == "lighting" || g.name == "emitters" || ImGui::TreeNode(g.name.data());
        if (!open) continue;
        ImGui::PushID(g.name.data());
        for (const Knob& k : g.knobs) {
            if (knobRelevant(k, edited)) changed |= drawKnob(k, edited);
        }
        ImGui::PopID();
        if (g.name != "lighting" && g.name != "emitters") ImGui::TreePop();
    }
    if (changed) {
        auto merged = engine::lighting::mergeLighting(edited, {});
        if (merged) {
            settings = *merged;
            mRefused.clear();
        } else {
            mRefused = merged.error().message;
        }
    }
    if (!mRefused.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "not applied: %s", mRefused.c_str());
        ImGui::PopTextWrapPos();
    }
    return changed && mRefused.empty();
}

}  // namespace game
