// Knobs of the displayed image's reconstruction (render/denoiser/, render/upsampling/): what a
// player sees is rebuilt from few shaded pixels, reused over frames, at the display's resolution.
#pragma once

#include <cstdint>

namespace engine::lighting {

enum class Display {
    Raw,        // the lit image as shaded, one sample per pixel at the render size
    Upsampled,  // jittered primary rays resolved over frames to the display size
    Denoised,   // the lighting denoised before that resolve (what vox play shows)
};

struct DisplaySettings {
    Display mode = Display::Raw;
    // Frames the denoiser's temporal mean holds at most: more is smoother on a still camera,
    // slower to follow a change its history does not see (an edit restarts it).
    std::uint32_t denoiseHistory = 32;
    // The denoiser's edge-stopped à-trous passes, with taps 1, 2, 4, ... pixels apart.
    std::uint32_t denoisePasses = 3;
    // Frames of display history the resolve holds at most on a still camera.
    std::uint32_t resolveHistory = 32;
    // The primary rays move by a sub-pixel jitter each frame, so the resolve anti-aliases; off:
    // pixel centres (the denoiser alone, on the samples every raw method shades).
    bool jitter = true;

    bool operator==(const DisplaySettings&) const = default;
};

}  // namespace engine::lighting
