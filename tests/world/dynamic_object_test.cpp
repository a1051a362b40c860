// Object paths: exact at keys, smooth between, periodic when looping, held when not.
#include "world/dynamic_object.h"

#include <gtest/gtest.h>

using namespace engine::world;

namespace {

ObjectPath squarePath(bool loop) {
    std::vector<ObjectKey> keys;
    const glm::dvec3 corners[] = {{0, 0, 0}, {10, 0, 0}, {10, 0, 10}, {0, 0, 10}, {0, 0, 0}};
    for (int i = 0; i < 5; ++i)
        keys.push_back({1.0 + i * 2.0, corners[i], rotationFromYawPitchRoll({90.0 * i, 0.0, 0.0})});
    return ObjectPath(keys, loop);
}

double angleBetween(glm::dquat a, glm::dquat b) {
    return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(a, b))));
}

}  // namespace

TEST(ObjectPath, PassesThroughEveryKeyExactly) {
    ObjectPath path = squarePath(false);
    for (const ObjectKey& k : path.keys()) {
        RigidTransform t = path.at(k.time);
        EXPECT_EQ(t.position, k.position) << k.time;
        EXPECT_EQ(t.rotation, k.rotation) << k.time;
    }
}

TEST(ObjectPath, LoopsWithItsPeriod) {
    ObjectPath path = squarePath(true);
    ASSERT_DOUBLE_EQ(path.period(), 8.0);
    for (double t : {1.3, 2.0, 4.75, 8.9}) {
        RigidTransform a = path.at(t), b = path.at(t + 8.0), c = path.at(t - 24.0);
        EXPECT_NEAR(glm::length(a.position - b.position), 0.0, 1e-9) << t;
        EXPECT_NEAR(glm::length(a.position - c.position), 0.0, 1e-9) << t;
        EXPECT_NEAR(angleBetween(a.rotation, b.rotation), 0.0, 1e-6) << t;
    }
    // Keys repeat every period.
    EXPECT_NEAR(glm::length(path.at(1.0 + 3 * 8.0 + 2.0).position - glm::dvec3(10, 0, 0)), 0.0,
                1e-9);
}

TEST(ObjectPath, OpenPathHoldsAtItsEnds) {
    ObjectPath path = squarePath(false);
    EXPECT_EQ(path.at(-5.0).position, glm::dvec3(0.0));
    EXPECT_EQ(path.at(100.0).position, path.keys().back().position);
}

TEST(ObjectPath, MotionIsSmoothAcrossKeysAndTheWrap) {
    // C1: the velocity just before a key equals the one just after (finite differences).
    ObjectPath path = squarePath(true);
    const double h = 1e-4;
    for (double key : {3.0, 5.0, 9.0 /* the wrap */}) {
        glm::dvec3 before = (path.at(key - h).position - path.at(key - 2 * h).position) / h;
        glm::dvec3 after = (path.at(key + 2 * h).position - path.at(key + h).position) / h;
        EXPECT_LT(glm::length(before - after), 0.05 * std::max(1.0, glm::length(before))) << key;
        EXPECT_GT(glm::length(before), 1.0) << "the object keeps moving through key " << key;
    }
}

TEST(ObjectPath, RotationTakesTheShortArcAtConstantSpeed) {
    ObjectPath path = squarePath(false);
    // Halfway between yaw 0 and yaw 90: yaw 45.
    EXPECT_NEAR(angleBetween(path.at(2.0).rotation, rotationFromYawPitchRoll({45, 0, 0})), 0.0,
                1e-9);
    EXPECT_NEAR(angleBetween(path.at(1.5).rotation, rotationFromYawPitchRoll({22.5, 0, 0})), 0.0,
                1e-9);
}

TEST(ObjectPath, IsAFunctionOfTimeAlone) {
    ObjectPath a = squarePath(true), b = squarePath(true);
    for (double t = -3.0; t < 20.0; t += 0.37) {
        EXPECT_EQ(a.at(t).position, b.at(t).position);
        EXPECT_EQ(a.at(t).rotation, a.at(t).rotation);
    }
}

TEST(DynamicObject, PivotIsTheModelCentre) {
    DynamicObject o;
    o.modelSize = {6, 4, 2};
    RigidTransform t{{20, 30, 40}, rotationFromYawPitchRoll({37, 11, -5})};
    glm::dvec3 centre(o.worldFromModel(t) * glm::dvec4(3, 2, 1, 1));
    EXPECT_NEAR(glm::length(centre - glm::dvec3(20, 30, 40)), 0.0, 1e-12);
    Box b = o.worldBounds(RigidTransform{{20, 30, 40}, {}});
    EXPECT_EQ(b.min, glm::ivec3(17, 28, 39));
    EXPECT_EQ(b.max, glm::ivec3(23, 32, 41));
}
