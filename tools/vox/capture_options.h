// The options of `vox capture` (docs/CAPTURE.md), shared by its parts.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "lighting_options.h"

namespace vox {

struct CaptureOptions {
    std::string world;
    std::string path;
    std::string out;
    std::string size = "320x180";
    std::optional<double> fps;  // absent: the path file's
    std::string frames;
    std::uint32_t warmup = 30;
    bool exr = false;
    bool noVideo = false;
    std::uint32_t sheet = 24;
    float exposure = 1.0f;
    LightingOptions lighting;
};

}  // namespace vox
