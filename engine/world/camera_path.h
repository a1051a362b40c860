// Camera paths: keyframes (time, position, target, vertical FOV) joined by a cubic Hermite
// spline whose tangents are Catmull–Rom finite differences over the key *times*, so the camera
// passes through every key and its velocity is continuous (C1) even when keys are unevenly
// spaced in time. Position, target and FOV are splined independently. Before the first key and
// after the last the camera holds still.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "world/scene.h"

namespace engine::world {

struct CameraKey {
    double time = 0.0;  // seconds
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f, 0.0f, 1.0f};
    float fovYDegrees = 60.0f;
};

class CameraPath {
public:
    CameraPath() = default;
    // Keys must be sorted by strictly increasing time (the path file checks that); at least one.
    explicit CameraPath(std::vector<CameraKey> keys);

    bool empty() const { return mKeys.empty(); }
    const std::vector<CameraKey>& keys() const { return mKeys; }
    double startTime() const { return mKeys.empty() ? 0.0 : mKeys.front().time; }
    double endTime() const { return mKeys.empty() ? 0.0 : mKeys.back().time; }

    // The camera at time t (seconds), named `name`.
    CameraPreset at(double t, const std::string& name = "path") const;
    // The spline itself at t, in double precision (what `at` rounds to a CameraPreset).
    struct Sample {
        glm::dvec3 position, target;
        double fovYDegrees;
    };
    Sample sample(double t) const;

private:
    std::vector<CameraKey> mKeys;
};

}  // namespace engine::world
