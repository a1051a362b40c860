// Knobs of the display's exposure (render/exposure/): fixed (the frame settings' exposure, the
// HUD slider, `--exposure`) or automatic, metered from the lit image.
#pragma once

namespace engine::lighting {

struct ExposureSettings {
    bool automatic = false;
    // Exposure = key / the metered luminance (the mean log2 luminance of the brighter half of
    // the lit pixels): 0.4 keeps the sandbox's direct light near the fixed exposure 1.
    float key = 0.4f;
    float adaptation = 0.1f;  // fraction of the way (in stops) to the metered exposure per frame

    bool operator==(const ExposureSettings&) const = default;
};

}  // namespace engine::lighting
