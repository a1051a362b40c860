// An edit shows in the very next frame, and that frame uploads only the bricks the edit
// touched (the renderer's upload counter); undoing it restores the previous image exactly.
#include <gtest/gtest.h>

#include "game/camera_controller.h"
#include "game/edit_tools.h"
#include "game/undo_history.h"
#include "gpu/gpu_test_context.h"
#include "render/renderer.h"
#include "world/world_edits.h"

using namespace engine::world;
using engine::render::FrameImages;
using engine::render::FrameSettings;
using engine::render::Renderer;
using gpu_testing::GpuTest;

class EditLatency : public GpuTest {};

TEST_F(EditLatency, NextFrameShowsTheEditAndUploadsOnlyTouchedBricks) {
    BrickGrid grid({128, 48, 128});
    fillBox(grid, Box{{0, 0, 0}, {128, 12, 128}}, 1);
    fillBox(grid, Box{{40, 12, 40}, {60, 30, 61}}, 2);
    Scene scene = gpu_testing::sceneWith(std::move(grid));
    game::CameraController camera;
    camera.setFromPreset({"test", {20.0f, 40.0f, 10.0f}, {70.0f, 11.0f, 70.0f}, 50.0f});
    FrameSettings settings;
    settings.width = 97;  // odd: the centre pixel's ray is the crosshair's
    settings.height = 55;

    // Preview lighting is deterministic, so "undo restores the image" can be exact.
    engine::lighting::LightingSettings lighting;
    lighting.method = engine::lighting::Method::Preview;
    Renderer renderer(gpu_testing::context());
    auto first = renderer.render(scene, camera.preset(), settings, lighting);
    EXPECT_TRUE(first.upload.full);
    FrameImages before = renderer.readback();
    auto idle = renderer.render(scene, camera.preset(), settings, lighting);
    EXPECT_EQ(idle.upload.bricks, 0u);
    EXPECT_EQ(idle.upload.cells, 0u);

    // Place one voxel where the crosshair points, as the sandbox does on a click.
    game::Pick target = game::pick(scene.grid, camera.position(), camera.forward());
    ASSERT_TRUE(target.hit);
    game::EditTools tools;
    tools.material = 3;
    auto op = tools.press(target);
    ASSERT_TRUE(op);
    game::UndoHistory history(1 << 20);
    game::EditRecord rec = history.record(scene.grid, op->region(), "place",
                                          [&](BrickGrid& g) { game::applyEdit(g, *op); });
    ASSERT_EQ(rec.changedCells, 1u);

    auto next = renderer.render(scene, camera.preset(), settings, lighting);
    EXPECT_FALSE(next.upload.full);
    EXPECT_LE(next.upload.bricks, rec.changedCells);
    EXPECT_LE(next.upload.cells, rec.changedCells);
    EXPECT_GE(next.upload.bricks + next.upload.cells, 1u);
    FrameImages after = renderer.readback();
    int showsVoxel = 0, changed = 0;
    glm::ivec3 placed = op->box.min;
    for (std::size_t i = 0; i < after.rgba8.size(); ++i) {
        showsVoxel += glm::ivec3(after.gbuffer[i].voxel) == placed && after.gbuffer[i].data.x == 3u;
        changed += after.rgba8[i] != before.rgba8[i];
    }
    EXPECT_GT(showsVoxel, 0) << "the placed voxel is not in the next frame";
    EXPECT_GT(changed, 0);
    // The pixel at the crosshair (image centre) sees the placed voxel.
    std::size_t centre = std::size_t(settings.height / 2) * settings.width + settings.width / 2;
    EXPECT_EQ(glm::ivec3(after.gbuffer[centre].voxel), placed);

    ASSERT_FALSE(history.undo(scene.grid).empty());
    auto undone = renderer.render(scene, camera.preset(), settings, lighting);
    EXPECT_LE(undone.upload.bricks + undone.upload.cells, 2u);
    FrameImages restored = renderer.readback();
    EXPECT_EQ(restored.rgba8, before.rgba8);
}
