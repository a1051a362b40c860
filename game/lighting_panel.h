// The HUD's lighting panel, drawn from the knob tables (lighting/lighting_knobs.h): one widget per
// knob that matters for the current method, grouped by technique, with the knob's own range. An
// edit goes through the same merge and validation as the command line; one that validation
// refuses is not applied and its message is shown instead (wrapped to the panel).
#pragma once

#include <string>

#include "lighting/lighting_settings.h"

namespace game {

class LightingPanel {
public:
    // Draws inside the current ImGui window, text wrapped to `width` pixels; true when
    // `settings` changed.
    bool draw(engine::lighting::LightingSettings& settings, float width);

private:
    std::string mRefused;  // the last refused edit's message
};

}  // namespace game
