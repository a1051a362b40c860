// Scripted input for tests and demos (`vox play --script FILE`): a list of timed input events
// replayed by frame number, never by wall clock, so a run is repeatable. While a script plays,
// the sandbox advances time by a fixed step per frame and ignores live input.
//
// Format: one step per line, `FRAME COMMAND ARGS...`; `#` starts a comment. FRAME is absolute,
// or `+N` for N frames after the previous step. Commands:
//   key NAME down|up         press or release a key (names: game/input.h)
//   tap NAME                 press now, release on the next frame
//   click BUTTON             left|right|middle: press now, release on the next frame
//   button BUTTON down|up
//   move DX DY               mouse motion in window pixels (mouse look while captured)
//   cursor X Y               put the cursor at window pixel (X, Y) (for the HUD)
//   scroll DY                wheel steps
//   screenshot FILE          the rendered image (render resolution, no HUD) to PNG
//   capture FILE             the window as presented (with the HUD) to PNG
//   resize W H               resize the window (the swapchain and render size follow)
//   quit                     as the window's close button (warns about unsaved changes)
// Actions run after the frame's input is handled, on the frame that was just presented.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "game/input.h"

namespace game {

struct ScriptAction {
    enum class Kind { Screenshot, Capture, Resize, Quit };
    Kind kind = Kind::Quit;
    std::string path;
    glm::uvec2 size{0};  // Resize
};

struct ScriptStep {
    std::uint64_t frame = 0;
    int line = 0;
    bool isAction = false;
    InputEvent event;
    ScriptAction action;
};

class ScriptPlayer {
public:
    static engine::Result<ScriptPlayer> parse(std::string_view text, std::string_view sourceName);
    static engine::Result<ScriptPlayer> load(const std::filesystem::path& path);

    // Input events and actions scheduled for `frame`, in file order.
    std::vector<InputEvent> eventsFor(std::uint64_t frame) const;
    std::vector<ScriptAction> actionsFor(std::uint64_t frame) const;
    // The frame of the last step; the sandbox quits after it if the script did not.
    std::uint64_t lastFrame() const { return mSteps.empty() ? 0 : mSteps.back().frame; }
    const std::vector<ScriptStep>& steps() const { return mSteps; }

private:
    std::vector<ScriptStep> mSteps;  // sorted by frame, stable
};

}  // namespace game
