#include "world/dynamic_object.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

#include "core/check.h"

namespace engine::world {

glm::dquat rotationFromYawPitchRoll(glm::dvec3 degrees) {
    glm::dvec3 r = glm::radians(degrees);
    return glm::angleAxis(r.x, glm::dvec3(0, 1, 0)) * glm::angleAxis(r.y, glm::dvec3(1, 0, 0)) *
           glm::angleAxis(r.z, glm::dvec3(0, 0, 1));
}

glm::dquat rotationFromAxisAngle(glm::dvec3 axis, double degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

ObjectPath::ObjectPath(std::vector<ObjectKey> keys, bool loop)
    : mKeys(std::move(keys)), mLoop(loop) {
    CHECK(!mKeys.empty());
    for (std::size_t i = 1; i < mKeys.size(); ++i) CHECK(mKeys[i].time > mKeys[i - 1].time);
    for (ObjectKey& k : mKeys) k.rotation = glm::normalize(k.rotation);
}

// Catmull–Rom tangent over uneven key times (as world/camera_path.cpp). A looping path's ends
// take their neighbours across the wrap (key n-1 is key 0 one period later); an open path's
// ends are one-sided.
glm::dvec3 ObjectPath::tangent(std::size_t k) const {
    const std::size_t n = mKeys.size();
    auto at = [&](std::ptrdiff_t i) -> std::pair<double, glm::dvec3> {
        if (!mLoop || n < 3) {
            std::size_t c = std::size_t(std::clamp<std::ptrdiff_t>(i, 0, std::ptrdiff_t(n) - 1));
            return {mKeys[c].time, mKeys[c].position};
        }
        if (i < 0) return {mKeys[n - 2].time - period(), mKeys[n - 2].position};
        if (i >= std::ptrdiff_t(n)) return {mKeys[1].time + period(), mKeys[1].position};
        return {mKeys[std::size_t(i)].time, mKeys[std::size_t(i)].position};
    };
    auto [ta, pa] = at(std::ptrdiff_t(k) - 1);
    auto [tb, pb] = at(std::ptrdiff_t(k) + 1);
    return (pb - pa) / (tb - ta);
}

RigidTransform ObjectPath::at(double t) const {
    const ObjectKey& first = mKeys.front();
    auto hold = [](const ObjectKey& k) { return RigidTransform{k.position, k.rotation}; };
    if (mKeys.size() == 1) return hold(first);
    if (mLoop) {
        // fmod keeps the phase exact for times that are whole periods past a key.
        double phase = std::fmod(t - first.time, period());
        if (phase < 0.0) phase += period();
        t = first.time + phase;
    }
    if (t <= first.time) return hold(first);
    if (t >= mKeys.back().time) return hold(mKeys.back());

    auto after = std::upper_bound(mKeys.begin(), mKeys.end(), t,
                                  [](double v, const ObjectKey& k) { return v < k.time; });
    std::size_t k = std::size_t(after - mKeys.begin()) - 1;
    const ObjectKey& k0 = mKeys[k];
    const ObjectKey& k1 = mKeys[k + 1];
    double dt = k1.time - k0.time;
    double s = (t - k0.time) / dt;
    if (s == 0.0) return hold(k0);  // exact at keys (slerp's sin ratios are not)
    double s2 = s * s, s3 = s2 * s;
    double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s;
    double h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
    RigidTransform out;
    out.position = h00 * k0.position + (h10 * dt) * tangent(k) + h01 * k1.position +
                   (h11 * dt) * tangent(k + 1);
    out.rotation = glm::slerp(k0.rotation, k1.rotation, s);  // shortest arc
    return out;
}

glm::dmat4 DynamicObject::worldFromModel(const RigidTransform& t) const {
    return glm::translate(glm::dmat4(1.0), t.position) * glm::mat4_cast(t.rotation) *
           glm::translate(glm::dmat4(1.0), -pivot());
}

Box DynamicObject::worldBounds(const RigidTransform& t) const {
    glm::dmat4 m = worldFromModel(t);
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int c = 0; c < 8; ++c) {
        glm::dvec3 corner((c & 1) ? modelSize.x : 0, (c & 2) ? modelSize.y : 0,
                          (c & 4) ? modelSize.z : 0);
        glm::dvec3 w(m * glm::dvec4(corner, 1.0));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    return Box{glm::ivec3(glm::floor(lo)), glm::ivec3(glm::ceil(hi))};
}

RigidTransform DynamicObject::poseAt(double t) const {
    if (!startTime) return path.at(t);
    const double first = path.keys().front().time;
    return path.at(t < *startTime ? first : first + (t - *startTime));
}

}  // namespace engine::world
