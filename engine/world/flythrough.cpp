#include "world/flythrough.h"

#include <cmath>

namespace engine::world {

std::uint32_t Flythrough::frameCount(double framesPerSecond) const {
    // The tolerance keeps 5 s at 30 fps at 151 frames despite rounding in duration * fps.
    return static_cast<std::uint32_t>(std::floor(duration * framesPerSecond + 1e-6)) + 1;
}

Status Flythrough::checkFrames(double framesPerSecond) const {
    std::uint32_t n = frameCount(framesPerSecond);
    for (std::uint32_t i = 0; i < n; ++i) {
        double t = frameTime(i, framesPerSecond);
        CameraPath::Sample s = camera.sample(t);
        if (!(s.fovYDegrees > 1.0 && s.fovYDegrees < 179.0))
            return makeError(
                "{}: at t = {:.3f} s (frame {}) the spline's fov is {:.1f} degrees, outside (1, "
                "179); "
                "add keys or smooth the fov",
                source, t, i, s.fovYDegrees);
        if (glm::length(s.target - s.position) < 1e-3)
            return makeError(
                "{}: at t = {:.3f} s (frame {}) the spline's target meets its position; move the "
                "targets "
                "further from the path",
                source, t, i);
    }
    return {};
}

}  // namespace engine::world
