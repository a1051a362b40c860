// Flythrough: a camera path plus a timeline of world events, read from the [path] table of a
// scene file or a path file (scene/path_file.h, format in worlds/README.md). Played at a
// frame rate, frame i shows time i / fps: its camera and world state are pure functions of the
// file, the frame rate and i.
#pragma once

#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/number_check.h"
#include "world/camera_path.h"
#include "world/timeline.h"

namespace engine::world {

// Frame rates of a path file's fps and of vox capture --fps.
inline constexpr NumberRange kFpsRange = aboveRange(0.0, 1000.0, "frames per second");

struct Flythrough {
    std::string source;     // the file it came from, for messages
    double fps = 30.0;      // the file's frame rate (a capture may override it)
    double duration = 0.0;  // seconds; frames run from time 0 to the last i / fps <= duration
    CameraPath camera;
    Timeline timeline;

    std::uint32_t frameCount(double framesPerSecond) const;
    static double frameTime(std::uint32_t frame, double framesPerSecond) {
        return double(frame) / framesPerSecond;
    }
    // Checks every frame's camera at this frame rate: the spline may overshoot between keys
    // (a FOV out of range, the target passing through the position).
    Status checkFrames(double framesPerSecond) const;
};

}  // namespace engine::world
