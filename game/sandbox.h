// The play/edit sandbox behind `vox play`: a window showing the renderer's image, a fly camera,
// edit tools with undo, a HUD, saving and autosaving. One frame of the loop:
//   input (live, or a script's events for this frame) -> camera, tools, edits -> HUD ->
//   render + present -> the frame's script actions, edit report, autosave.
// Edits are applied before the frame is rendered, so an edit shows in the next presented frame,
// and only the bricks it touched are uploaded (the upload counter is printed per edit).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "game/streamed_world.h"
#include "lighting/lighting_knobs.h"
#include "world/player_body.h"

namespace game {

struct PlayOptions {
    std::string world;     // name or path; empty: the default world
    std::string savePath;  // empty: the world itself if it is a save, else saves/NAME.toml
    std::string camera;    // preset to start from; empty: the first
    glm::uvec2 windowSize{1280, 720};
    float renderScale = 0.25f;  // render resolution as a fraction of the window's (the start value)
    bool autoScale = true;      // then adapt it to keep frames near targetFrameMs
    double targetFrameMs = 90.0;  // wall time per frame the automatic render scale aims at
    std::string scriptPath;       // replay scripted input (fixed time step, live input ignored)
    std::uint64_t maxFrames = 0;  // quit after this many frames; 0: no limit
    std::string editLogPath;      // write every edit, undo, redo, save and screenshot view here
    std::string frameLogPath;  // CSV, one row per frame: wall, render call and GPU ms, render size
    std::string walkLogPath;   // CSV, one row per frame: walk or fly, the player's box
                               // (game/walk_controller.h)
    bool walk = false;         // start in walk mode (F toggles it)
    engine::world::PlayerSettings player;  // the walking player's size (scale), speeds, gravity
    double autosaveMinutes = 3.0;          // 0: off
    std::size_t undoMegabytes = 256;
    // Models the object tool (key 4) places: scene files, .vdb or .vox (game/object_tools.h).
    std::vector<std::string> models;
    // The command line's lighting knobs, merged over the world's own settings
    // (scene/scene_lighting.h: the same merge as vox render); switchable live in the HUD.
    std::vector<engine::lighting::KnobValue> lighting;
    bool hud = true;
    StreamOptions stream;         // regions streamed around the camera (game/streamed_world.h)
    bool captureCommand = false;  // `vox capture` exists: the no-display message points to it too
};

// Runs the sandbox; prints its own errors (one line) and returns the process exit code.
int runPlay(const PlayOptions& options);

// The one-line message `vox play` prints when there is no display (or it cannot be opened).
std::string noDisplayMessage(const std::string& why, bool captureCommand);

}  // namespace game
