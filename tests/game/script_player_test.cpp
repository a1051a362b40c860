// Scripts parse into frame-numbered events; mistakes name the file and line.
#include "game/script_player.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "game/camera_controller.h"
#include "game/render_scale_controller.h"

using game::InputEventType;
using game::ScriptPlayer;

TEST(ScriptPlayer, ParsesAbsoluteAndRelativeFramesTapsAndActions) {
    auto script = ScriptPlayer::parse(R"(# a comment
0 key W down
+10 key w up      # relative to the line before
12 tap ctrl
12 move 3.5 -2
+3 click left
20 screenshot out/a.png
20 capture out/b.png
20 resize 640 360
21 quit
)",
                                      "test.script");
    ASSERT_TRUE(script.ok()) << script.error().message;
    auto f0 = script->eventsFor(0);
    ASSERT_EQ(f0.size(), 1u);
    EXPECT_EQ(f0[0].type, InputEventType::Key);
    EXPECT_EQ(f0[0].code, GLFW_KEY_W);
    EXPECT_TRUE(f0[0].down);
    ASSERT_EQ(script->eventsFor(10).size(), 1u);
    EXPECT_FALSE(script->eventsFor(10)[0].down);
    auto f12 = script->eventsFor(12);
    ASSERT_EQ(f12.size(), 2u);
    EXPECT_EQ(f12[0].code, GLFW_KEY_LEFT_CONTROL);
    EXPECT_EQ(f12[1].type, InputEventType::MouseMove);
    EXPECT_EQ(f12[1].value, glm::vec2(3.5f, -2.0f));
    ASSERT_EQ(script->eventsFor(13).size(), 1u);  // the tap's release
    EXPECT_FALSE(script->eventsFor(13)[0].down);
    ASSERT_EQ(script->eventsFor(15).size(), 1u);
    EXPECT_EQ(script->eventsFor(15)[0].type, InputEventType::MouseButton);
    EXPECT_EQ(script->eventsFor(16).size(), 1u);
    auto actions = script->actionsFor(20);
    ASSERT_EQ(actions.size(), 3u);
    EXPECT_EQ(actions[2].kind, game::ScriptAction::Kind::Resize);
    EXPECT_EQ(actions[2].size, glm::uvec2(640, 360));
    EXPECT_EQ(actions[0].kind, game::ScriptAction::Kind::Screenshot);
    EXPECT_EQ(actions[0].path, "out/a.png");
    EXPECT_EQ(actions[1].kind, game::ScriptAction::Kind::Capture);
    EXPECT_EQ(script->actionsFor(21).size(), 1u);
    EXPECT_EQ(script->lastFrame(), 21u);
}

TEST(ScriptPlayer, ErrorsNameFileAndLine) {
    auto expectError = [](const char* text, const char* fragment) {
        auto s = ScriptPlayer::parse(text, "bad.script");
        ASSERT_FALSE(s.ok()) << text;
        EXPECT_NE(s.error().message.find(fragment), std::string::npos) << s.error().message;
    };
    expectError("0 key W down\n1 key Nope down\n", "bad.script:2: unknown key 'Nope'");
    expectError("5 tap W\n3 tap W\n", "bad.script:2: frame 3 comes before");
    expectError("x tap W\n", "bad.script:1: 'x' is not a frame number");
    expectError("0 click sideways\n", "unknown mouse button");
    expectError("0 fly away\n", "bad.script:1: unknown command");
    expectError("0 key W sideways\n", "expected 'down' or 'up'");
    expectError("0 resize 0 10\n",
                "bad.script:1: resize x must be positive, not 0; allowed: 1..8192 pixels");
    // Numbers go through the one number check: no NaN or infinite mouse motion reaches the camera.
    expectError("0 move nan 0\n", "bad.script:1: move x must be a finite number");
    expectError("0 move 0 inf\n", "bad.script:1: move y must be a finite number");
    expectError("0 cursor 1e300 0\n", "bad.script:1: cursor x is too large (max 1000000)");
    expectError("0 scroll -inf\n", "bad.script:1: scroll steps must be a finite number");
    expectError("0 resize 640.5 360\n", "bad.script:1: resize x must be a whole number");
    expectError("0 move 1,5 0\n", "bad.script:1: move x: expected a number");
}

TEST(CameraController, SameInputSameFlightAndPresetsRoundTrip) {
    engine::world::CameraPreset start{"start", {10.0f, 20.0f, 30.0f}, {40.0f, 10.0f, 90.0f}, 50.0f};
    auto fly = [&] {
        game::CameraController cam;
        cam.setFromPreset(start);
        game::InputState input;
        for (int frame = 0; frame < 60; ++frame) {
            input.beginFrame();
            if (frame == 0) input.apply({InputEventType::Key, GLFW_KEY_W, true, {}});
            if (frame == 30) input.apply({InputEventType::Key, GLFW_KEY_LEFT_SHIFT, true, {}});
            if (frame % 7 == 0) input.apply({InputEventType::MouseMove, 0, false, {5.0f, -3.0f}});
            cam.update(input, 1.0f / 30.0f, true);
        }
        return cam.preset();
    };
    engine::world::CameraPreset a = fly(), b = fly();
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.target, b.target);
    EXPECT_GT(glm::length(a.position - start.position), 30.0f);

    game::CameraController cam;
    cam.setFromPreset(start);
    glm::vec3 want = glm::normalize(start.target - start.position);
    EXPECT_LT(glm::length(cam.forward() - want), 1e-5f);
    EXPECT_EQ(cam.preset().position, start.position);
    // Right matches the renderer's basis (forward x world up).
    EXPECT_LT(
        glm::length(cam.right() - glm::normalize(glm::cross(cam.forward(), glm::vec3(0, 1, 0)))),
        1e-5f);
}

TEST(RenderScaleController, SettlesNearTheTargetAndIgnoresNoise) {
    // A device where a frame costs 400 ms at full resolution (time ~ pixels ~ scale^2).
    game::RenderScaleController c(66.0, 1.0f / 16.0f, 1.0f);
    float scale = 0.25f;
    int changes = 0;
    for (int frame = 0; frame < 400; ++frame) {
        float next = c.update(scale, 400.0 * scale * scale);
        changes += next != scale;
        scale = next;
    }
    double ms = 400.0 * scale * scale;
    EXPECT_GE(ms, 66.0 * 0.7);
    EXPECT_LE(ms, 66.0);
    EXPECT_LE(changes, 4);  // a few steps, then it holds
    // Within the band, noise changes nothing.
    game::RenderScaleController steady(66.0, 1.0f / 16.0f, 1.0f);
    for (int frame = 0; frame < 200; ++frame)
        EXPECT_EQ(steady.update(0.3f, frame % 2 ? 50.0 : 64.0), 0.3f);
}

// Frames at the window's size (resolve, tonemap, present, host work) do not shrink with the
// render scale: a controller that took the whole frame to scale would undershoot, step after
// step. From two scales it finds the fixed part and lands in the band.
TEST(RenderScaleController, FindsTheFixedPartOfAFrame) {
    auto frameMs = [](float s) { return 60.0 + 400.0 * s * s; };
    game::RenderScaleController c(90.0, 1.0f / 16.0f, 1.0f);
    float scale = 0.5f;  // 160 ms
    int changes = 0;
    for (int frame = 0; frame < 400; ++frame) {
        float next = c.update(scale, frameMs(scale));
        changes += next != scale;
        scale = next;
    }
    EXPECT_NEAR(c.fixedMs(), 60.0, 1e-6);
    EXPECT_GE(frameMs(scale), 90.0 * 0.7);
    EXPECT_LE(frameMs(scale), 90.0);
    EXPECT_LE(changes, 2);
}

// A fixed part above the target: the smallest render size is the best there is, and it stays.
TEST(RenderScaleController, AFixedPartOverTheTargetGoesToTheSmallestScale) {
    auto frameMs = [](float s) { return 120.0 + 400.0 * s * s; };
    game::RenderScaleController c(90.0, 1.0f / 16.0f, 1.0f);
    float scale = 0.5f;
    for (int frame = 0; frame < 600; ++frame) scale = c.update(scale, frameMs(scale));
    EXPECT_EQ(scale, 1.0f / 16.0f);
}
