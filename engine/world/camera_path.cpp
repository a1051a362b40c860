#include "world/camera_path.h"

#include <algorithm>
#include <utility>

#include "core/check.h"

namespace engine::world {

namespace {

// Cubic Hermite on one segment of length dt, s in [0, 1]; m0 and m1 are derivatives per unit
// time, hence the dt factors.
template <typename T>
T hermite(const T& p0, const T& m0, const T& p1, const T& m1, double s, double dt) {
    double s2 = s * s, s3 = s2 * s;
    double h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    double h10 = s3 - 2.0 * s2 + s;
    double h01 = -2.0 * s3 + 3.0 * s2;
    double h11 = s3 - s2;
    return h00 * p0 + (h10 * dt) * m0 + h01 * p1 + (h11 * dt) * m1;
}

// Catmull–Rom tangent for uneven key times: the slope of the chord from the previous key to
// the next one; one-sided at the ends (so two keys give a straight line at constant speed).
template <typename T, typename Get>
T tangent(const std::vector<CameraKey>& keys, std::size_t k, Get get) {
    std::size_t a = k == 0 ? 0 : k - 1;
    std::size_t b = std::min(k + 1, keys.size() - 1);
    return (get(keys[b]) - get(keys[a])) / (keys[b].time - keys[a].time);
}

}  // namespace

CameraPath::CameraPath(std::vector<CameraKey> keys) : mKeys(std::move(keys)) {
    CHECK(!mKeys.empty());
    for (std::size_t i = 1; i < mKeys.size(); ++i) CHECK(mKeys[i].time > mKeys[i - 1].time);
}

CameraPath::Sample CameraPath::sample(double t) const {
    CHECK(!mKeys.empty());
    auto position = [](const CameraKey& k) { return glm::dvec3(k.position); };
    auto target = [](const CameraKey& k) { return glm::dvec3(k.target); };
    auto fov = [](const CameraKey& k) { return double(k.fovYDegrees); };
    auto holdAt = [&](const CameraKey& k) { return Sample{position(k), target(k), fov(k)}; };
    if (mKeys.size() == 1 || t <= mKeys.front().time) return holdAt(mKeys.front());
    if (t >= mKeys.back().time) return holdAt(mKeys.back());

    // The segment [k, k+1] holding t: the last key at or before t.
    auto after = std::upper_bound(mKeys.begin(), mKeys.end(), t,
                                  [](double v, const CameraKey& k) { return v < k.time; });
    std::size_t k = std::size_t(after - mKeys.begin()) - 1;
    const CameraKey& k0 = mKeys[k];
    const CameraKey& k1 = mKeys[k + 1];
    double dt = k1.time - k0.time;
    double s = (t - k0.time) / dt;
    Sample out;
    out.position = hermite(position(k0), tangent<glm::dvec3>(mKeys, k, position), position(k1),
                           tangent<glm::dvec3>(mKeys, k + 1, position), s, dt);
    out.target = hermite(target(k0), tangent<glm::dvec3>(mKeys, k, target), target(k1),
                         tangent<glm::dvec3>(mKeys, k + 1, target), s, dt);
    out.fovYDegrees = hermite(fov(k0), tangent<double>(mKeys, k, fov), fov(k1),
                              tangent<double>(mKeys, k + 1, fov), s, dt);
    return out;
}

CameraPreset CameraPath::at(double t, const std::string& name) const {
    Sample s = sample(t);
    return CameraPreset{name, glm::vec3(s.position), glm::vec3(s.target), float(s.fovYDegrees)};
}

}  // namespace engine::world
