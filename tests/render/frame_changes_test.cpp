// What changed since the last frame (render/frame_changes.h), worked out once per frame: the first
// frame has no history, a moved camera, an edited cell, a changed sky, an edited light, a new
// size and new settings each show, and a still frame shows nothing.
#include "render/frame_changes.h"

#include <gtest/gtest.h>

using namespace engine::render;
using engine::lighting::EmitterUpdateStats;
using engine::lighting::LightingSettings;
using engine::world::CameraPreset;
using engine::world::Scene;

namespace {

Scene emptyWorld() {
    Scene s;
    s.grid = engine::world::BrickGrid(glm::ivec3(32));
    return s;
}

struct Frame {
    Scene scene = emptyWorld();
    CameraPreset camera{"", {4, 4, -10}, {4, 4, 4}, 60.0f};
    glm::uvec2 size{32, 32};
    LightingSettings lighting;
    WorldUploadStats upload;
    EmitterUpdateStats emitters;
    EmitterUploadStats emitterUpload;

    FrameChanges observe(FrameChangeTracker& tracker) {
        FrameChanges c =
            tracker.observe({scene, camera, size, lighting, upload, emitters, emitterUpload});
        scene.grid.clearDirty();
        upload = {};
        emitters = {};
        emitterUpload = {};
        return c;
    }
};

}  // namespace

TEST(FrameChanges, AStillFrameAfterTheFirstChangesNothing) {
    FrameChangeTracker tracker;
    Frame f;
    const FrameChanges first = f.observe(tracker);
    EXPECT_TRUE(first.historyLost);
    EXPECT_TRUE(first.cameraMoved);
    EXPECT_TRUE(first.sizeChanged);
    EXPECT_FALSE(first.skyChanged);  // nothing to compare with
    EXPECT_EQ(first.previousCamera.position, f.camera.position);
    const FrameChanges still = f.observe(tracker);
    EXPECT_FALSE(still.historyLost);
    EXPECT_FALSE(still.cameraMoved);
    EXPECT_FALSE(still.sizeChanged);
    EXPECT_FALSE(still.settingsChanged);
    EXPECT_FALSE(still.worldChanged());
    EXPECT_FALSE(still.restartsAccumulation());
    EXPECT_TRUE(still.editedCells.empty());
}

TEST(FrameChanges, EachChangeShows) {
    FrameChangeTracker tracker;
    Frame f;
    f.observe(tracker);
    f.observe(tracker);

    const glm::vec3 from = f.camera.position;
    f.camera.position.x += 1.0f;
    FrameChanges c = f.observe(tracker);
    EXPECT_TRUE(c.cameraMoved);
    EXPECT_EQ(c.previousCamera.position, from);
    EXPECT_TRUE(c.restartsAccumulation());
    EXPECT_FALSE(c.historyLost);  // temporal reuse reprojects across a moving camera

    f.scene.grid.set({9, 1, 17}, 1);
    f.upload.bricks = 1;
    c = f.observe(tracker);
    ASSERT_EQ(c.editedCells.size(), 1u);
    EXPECT_EQ(c.editedCells[0], glm::ivec3(1, 0, 2));
    EXPECT_TRUE(c.staticWorldChanged);
    EXPECT_TRUE(c.worldChanged());

    f.scene.sky.sunDirection = glm::vec3(0, 1, 0);
    c = f.observe(tracker);
    EXPECT_TRUE(c.skyChanged);
    EXPECT_TRUE(c.restartsAccumulation());  // a running mean of the old sun's light is stale

    f.emitters.added = 1;
    f.emitterUpload.slots = 1;
    c = f.observe(tracker);
    EXPECT_TRUE(c.lightsEdited);
    EXPECT_TRUE(c.lightsUploaded);
    EXPECT_TRUE(c.historyLost);  // reservoirs of the old lights would be wrong

    f.upload.dynamicBytes = 64;
    EXPECT_TRUE(f.observe(tracker).objectsMoved);

    f.lighting.restir.candidates = 8;
    c = f.observe(tracker);
    EXPECT_TRUE(c.settingsChanged);
    EXPECT_TRUE(c.historyLost);

    f.size = {16, 16};
    c = f.observe(tracker);
    EXPECT_TRUE(c.sizeChanged);
    EXPECT_TRUE(c.historyLost);
    EXPECT_TRUE(c.cameraMoved);  // a new size starts without a previous view

    EXPECT_FALSE(f.observe(tracker).historyLost);
    tracker.forgetHistory();
    c = f.observe(tracker);
    EXPECT_TRUE(c.historyLost);
    EXPECT_TRUE(c.cameraMoved);
}

// A new world's full upload is not an edit of its lights: the history restarts from the new
// world's settings, not from lightsEdited.
TEST(FrameChanges, ANewWorldIsNotALightEdit) {
    FrameChangeTracker tracker;
    Frame f;
    f.observe(tracker);
    f.upload.full = true;
    f.emitters.full = true;
    f.emitters.added = 5;
    const FrameChanges c = f.observe(tracker);
    EXPECT_TRUE(c.newWorld);
    EXPECT_FALSE(c.lightsEdited);
}
