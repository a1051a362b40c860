// Walk mode's hooks into the sandbox (game/walk_controller.h): entering puts the body's eye at
// the camera, held keys walk along the view's heading, and place edits that would fill a voxel
// the body stands in are refused whatever the brush, while others go through.
#include "game/walk_controller.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "world/world_edits.h"

using namespace engine::world;

namespace {

constexpr MaterialId kStone = 1;

Scene flatScene() {
    Scene scene;
    scene.grid = BrickGrid({64, 32, 64});
    fillBox(scene.grid, Box{{0, 0, 0}, {64, 4, 64}}, kStone);
    return scene;
}

game::EditOp placeBox(Box box) {
    game::EditOp op;
    op.tool = game::Tool::Place;
    op.brush = box.size() == glm::ivec3(1) ? game::Brush::Voxel : game::Brush::Box;
    op.box = box;
    op.material = kStone;
    return op;
}

}  // namespace

TEST(WalkController, EntersUnderTheCameraAndWalksAlongTheHeading) {
    Scene scene = flatScene();
    game::CameraController camera;
    CameraPreset view;
    view.position = {20.5f, 12.0f, 20.5f};
    view.target = {20.5f, 12.0f, 40.0f};  // looking along +z
    camera.setFromPreset(view);
    game::WalkController walk;
    walk.toggle(scene, camera);
    ASSERT_TRUE(walk.active());
    EXPECT_NEAR(walk.body().eye().y, 12.0, 1e-6);
    game::InputState input;
    input.beginFrame();
    input.apply({game::InputEventType::Key, GLFW_KEY_W, true});
    double time = 0.0;
    for (int f = 0; f < 60; ++f) {
        time += 1.0 / 30.0;
        walk.update(input, 1.0 / 30.0, time, false, scene, camera);
        input.beginFrame();
    }
    EXPECT_NEAR(walk.body().feet().y, 4.0, 1e-3) << "fell to the ground";
    EXPECT_GT(walk.body().feet().z, 26.0) << "walked along +z";
    EXPECT_NEAR(walk.body().feet().x, 20.5, 1e-6);
    EXPECT_NEAR(camera.position().y, 4.0 + 1.62, 1e-3) << "the camera rides at the eye";
    EXPECT_EQ(walk.toggle(scene, camera), "fly mode (F walks)");
    EXPECT_FALSE(walk.active());
}

TEST(WalkController, RefusesPlaceEditsThatWouldEncloseThePlayer) {
    Scene scene = flatScene();
    game::CameraController camera;
    CameraPreset view;
    view.position = {20.5f, 5.62f, 20.5f};
    view.target = {20.5f, 5.62f, 40.0f};
    camera.setFromPreset(view);
    game::WalkController walk;
    EXPECT_EQ(walk.refusal(placeBox({{20, 4, 20}, {21, 5, 21}}), scene.grid), "")
        << "fly mode refuses nothing";
    walk.toggle(scene, camera);
    // The body spans x, z 20.2..20.8 and y 4..5.8: voxels (20, 4..5, 20).
    EXPECT_NE(walk.refusal(placeBox({{20, 4, 20}, {21, 5, 21}}), scene.grid), "");
    EXPECT_NE(walk.refusal(placeBox({{20, 5, 20}, {21, 6, 21}}), scene.grid), "")
        << "at head height";
    EXPECT_NE(walk.refusal(placeBox({{10, 0, 10}, {30, 30, 30}}), scene.grid), "")
        << "a box around it";
    game::EditOp sphere;
    sphere.tool = game::Tool::Place;
    sphere.brush = game::Brush::Sphere;
    sphere.center = {22.0f, 5.0f, 20.5f};
    sphere.radius = 2.0f;
    sphere.material = kStone;
    EXPECT_NE(walk.refusal(sphere, scene.grid), "") << "a sphere reaching it";
    sphere.center = {24.0f, 5.0f, 20.5f};
    EXPECT_EQ(walk.refusal(sphere, scene.grid), "") << "a sphere beside it";
    EXPECT_EQ(walk.refusal(placeBox({{21, 4, 20}, {22, 5, 21}}), scene.grid), "")
        << "the voxel beside it";
    EXPECT_EQ(walk.refusal(placeBox({{20, 6, 20}, {21, 7, 21}}), scene.grid), "")
        << "the voxel over its head";
    game::EditOp remove = placeBox({{20, 4, 20}, {21, 5, 21}});
    remove.tool = game::Tool::Remove;
    EXPECT_EQ(walk.refusal(remove, scene.grid), "");
}
