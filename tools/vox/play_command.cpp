// `vox play [WORLD]`: the play/edit sandbox (game/sandbox.h). This file only maps options.
#include "command_files.h"
#include "commands.h"
#include "game/sandbox.h"
#include "number_options.h"
#include "scene/scene_lighting.h"

namespace vox {

void addPlayCommand(CLI::App& app, int& exitCode) {
    auto* cmd =
        app.add_subcommand("play", "Play in and edit a world in a window (needs a display)");
    auto o = std::make_shared<game::PlayOptions>();
    auto size = std::make_shared<std::string>("1280x720");
    auto lighting = std::make_shared<LightingOptions>();
    cmd->add_option("world", o->world,
                    "World name (worlds/NAME.toml) or scene file; default: sandbox");
    cmd->add_option(
        "--save", o->savePath,
        "Where Ctrl+S saves (default: the world if it is a save, else saves/NAME.toml)");
    cmd->add_option("--camera", o->camera,
                    "Camera preset to start from (default: the scene's first)");
    cmd->add_option("--size", *size, "Window size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--render-scale", o->renderScale,
                    "Render resolution as a fraction of the window's (1/16..1); fixes it (default: "
                    "start at 0.25 and "
                    "adapt to keep frames near --target-ms)")
        ->check(numberIn(kRenderScaleRange));
    cmd->add_option("--target-ms", o->targetFrameMs,
                    "Wall time per frame the automatic render scale aims at (host work and the "
                    "window-size passes included)")
        ->capture_default_str()
        ->check(numberIn(engine::aboveRange(0.0, 10000.0, "ms")));
    cmd->add_option("--script", o->scriptPath,
                    "Replay scripted input from FILE (format: game/script_player.h)");
    cmd->add_option("--frames", o->maxFrames, "Quit after this many frames (0: no limit)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(0, 1e12, "frames")));
    cmd->add_option("--edit-log", o->editLogPath,
                    "Write every edit, undo, redo, save and screenshot to FILE");
    cmd->add_option(
        "--frame-log", o->frameLogPath,
        "Write per-frame times to FILE.csv (frame, wall ms, render call ms, GPU ms, render size)");
    cmd->add_option(
        "--walk-log", o->walkLogPath,
        "Write per-frame walk state to FILE.csv (mode, the player's box in voxels, collision ms)");
    cmd->add_flag("--walk", o->walk, "Start in walk mode (F toggles walking and flying)");
    cmd->add_option("--player-scale", o->player.scale,
                    "Size of the walking player: its 0.6 x 1.8 x 0.6 voxel box, step, jump and "
                    "speeds times S")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(0.05, 64.0)));
    cmd->add_option("--autosave-minutes", o->autosaveMinutes,
                    "Autosave interval to SAVE.autosave.toml (0: off)")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(0.0, 24.0 * 60.0, "minutes")));
    cmd->add_option("--undo-mb", o->undoMegabytes, "Memory budget of the undo history in MiB")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1 << 20, "MiB")));
    cmd->add_option(
        "--model", o->models,
        "A model the object tool (key 4) places: WORLD.toml, FILE.vdb or FILE.vox, at most 16384 "
        "solid voxels (repeat for more; M cycles them)");
    cmd->add_flag("!--no-hud", o->hud, "Start with the HUD hidden (Tab shows it)");
    cmd->add_option("--stream-radius", o->stream.radius,
                    "Stream the world's regions within R voxels of the camera (a store, or one "
                    "terrain generator; 0: load it whole; default: stream worlds wider than 2048 "
                    "at 768)")
        ->check(numberIn(engine::closedRange(0.0, 1e6, "voxels")));
    cmd->add_option("--stream-budget-mb", o->stream.budgetMiB,
                    "Memory budget of the streamed regions in MiB")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(16, 1 << 20, "MiB")));
    cmd->add_option("--stream-regions-per-frame", o->stream.regionsPerFrame,
                    "Streamed regions copied into the world per frame, at most")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 4096, "regions")));
    cmd->add_option("--stream-bricks-per-frame", o->stream.bricksPerFrame,
                    "Bricks of the streamed regions copied into the world per frame, at most (one "
                    "region always goes in, however many it has)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1 << 24, "bricks")));
    addLightingOptions(*cmd, *lighting);
    cmd->callback([o, size, lighting, cmd, &exitCode] {
        lighting->commandDefaults = engine::scene::playDefaults();
        if (lighting->showSettings) {
            exitCode = showSettings(o->world, *lighting);
            return;
        }
        o->lighting = lightingOverrides(*lighting);
        o->captureCommand =
            !cmd->get_parent()
                 ->get_subcommands([](const CLI::App* a) { return a->get_name() == "capture"; })
                 .empty();
        auto parsed = parseSize(*size, "--size");
        if (!parsed) {
            exitCode = fail(parsed.error());
            return;
        }
        o->windowSize = *parsed;
        // The logs and the save are never written over an input or over each other.
        std::vector<CommandFile> inputs{{"the world", worldFileOf(o->world)},
                                        {"--script", o->scriptPath}};
        for (const std::string& m : o->models) inputs.push_back({"--model", worldFileOf(m)});
        const std::vector<CommandFile> logs{{"--edit-log", o->editLogPath},
                                            {"--frame-log", o->frameLogPath},
                                            {"--walk-log", o->walkLogPath}};
        std::vector<CommandFile> outputs = logs;
        outputs.insert(outputs.begin(), {"--save", o->savePath});
        engine::Status s = checkCommandFiles(inputs, logs);
        if (s) s = checkCommandFiles({}, outputs);
        if (!s) {
            exitCode = fail(s.error());
            return;
        }
        o->autoScale = cmd->count("--render-scale") == 0;
        exitCode = game::runPlay(*o);
    });
}

}  // namespace vox
