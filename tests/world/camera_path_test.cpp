#include "world/camera_path.h"

#include <gtest/gtest.h>
#include <vector>

using namespace engine::world;

namespace {

// Unevenly spaced keys that turn in every axis: the case where a spline parameterised by key
// index instead of time would break C1.
std::vector<CameraKey> turningKeys() {
    return {
        {0.0, {0, 10, 0}, {50, 0, 50}, 50.0f},     {0.5, {20, 14, -5}, {60, 5, 40}, 60.0f},
        {2.0, {40, 30, 30}, {10, 0, 80}, 70.0f},   {2.3, {30, 25, 60}, {0, 10, 60}, 55.0f},
        {4.0, {-10, 40, 70}, {20, 20, 20}, 65.0f},
    };
}

CameraPath::Sample derivative(const CameraPath& path, double t0, double t1) {
    CameraPath::Sample a = path.sample(t0), b = path.sample(t1);
    double dt = t1 - t0;
    return {(b.position - a.position) / dt, (b.target - a.target) / dt,
            (b.fovYDegrees - a.fovYDegrees) / dt};
}

double maxDifference(const CameraPath::Sample& a, const CameraPath::Sample& b) {
    glm::dvec3 p = glm::abs(a.position - b.position), t = glm::abs(a.target - b.target);
    return std::max({p.x, p.y, p.z, t.x, t.y, t.z, std::abs(a.fovYDegrees - b.fovYDegrees)});
}

}  // namespace

TEST(CameraPath, PassesThroughEveryKey) {
    CameraPath path(turningKeys());
    for (const CameraKey& k : turningKeys()) {
        CameraPreset c = path.at(k.time);
        EXPECT_EQ(c.position, k.position) << "t = " << k.time;
        EXPECT_EQ(c.target, k.target) << "t = " << k.time;
        EXPECT_EQ(c.fovYDegrees, k.fovYDegrees) << "t = " << k.time;
    }
}

// C1: the one-sided derivatives just left and right of every interior key agree, while the
// velocity itself is far from zero there (so the check is not vacuous). With h = 1e-5 s the
// one-sided differences carry O(h * second derivative) error: a few 1e-3 here. A path with a
// kink (linear interpolation) differs by the change in slope, units per second.
TEST(CameraPath, VelocityIsContinuousAtKeys) {
    CameraPath path(turningKeys());
    const double h = 1e-5;
    const auto keys = turningKeys();
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        double t = keys[i].time;
        CameraPath::Sample left = derivative(path, t - h, t), right = derivative(path, t, t + h);
        EXPECT_LT(maxDifference(left, right), 0.02) << "key " << i;
        EXPECT_GT(glm::length(left.position), 5.0) << "key " << i;
    }
    // And between keys the curve is smooth too (a cubic): sample the middle of each segment.
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        double t = 0.5 * (keys[i].time + keys[i + 1].time);
        EXPECT_LT(maxDifference(derivative(path, t - h, t), derivative(path, t, t + h)), 0.02)
            << "segment " << i;
    }
}

// The check above can fail: a polyline through the same keys has a kink at every key.
TEST(CameraPath, KinkDetectorSeesAPolyline) {
    const auto keys = turningKeys();
    auto lerpAt = [&](double t) {
        std::size_t i = 0;
        while (i + 2 < keys.size() && t > keys[i + 1].time) ++i;
        double s = (t - keys[i].time) / (keys[i + 1].time - keys[i].time);
        return glm::mix(glm::dvec3(keys[i].position), glm::dvec3(keys[i + 1].position), s);
    };
    const double h = 1e-5, t = keys[1].time;
    glm::dvec3 left = (lerpAt(t) - lerpAt(t - h)) / h, right = (lerpAt(t + h) - lerpAt(t)) / h;
    EXPECT_GT(glm::length(left - right), 1.0);
}

TEST(CameraPath, TwoKeysMoveInAStraightLineAtConstantSpeed) {
    CameraPath path({{1.0, {0, 0, 0}, {0, 0, 10}, 40.0f}, {3.0, {10, 20, -4}, {0, 0, 10}, 80.0f}});
    for (double t : {1.25, 1.5, 2.0, 2.75}) {
        CameraPath::Sample s = path.sample(t);
        double f = (t - 1.0) / 2.0;
        EXPECT_NEAR(s.position.x, 10.0 * f, 1e-9);
        EXPECT_NEAR(s.position.y, 20.0 * f, 1e-9);
        EXPECT_NEAR(s.position.z, -4.0 * f, 1e-9);
        EXPECT_NEAR(s.fovYDegrees, 40.0 + 40.0 * f, 1e-9);
    }
}

TEST(CameraPath, HoldsStillOutsideItsKeys) {
    CameraPath path(turningKeys());
    EXPECT_EQ(path.at(-1.0).position, turningKeys().front().position);
    EXPECT_EQ(path.at(99.0).position, turningKeys().back().position);
    CameraPath single({{0.0, {1, 2, 3}, {4, 5, 6}, 33.0f}});
    EXPECT_EQ(single.at(7.0).position, glm::vec3(1, 2, 3));
    EXPECT_EQ(single.at(7.0).fovYDegrees, 33.0f);
}
