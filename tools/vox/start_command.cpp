// `vox start [WORLD]`: the Quick start's first command. With a display it opens the sandbox on
// the world; without one it renders the world headless to out/render.png, as `vox render`
// does. Either way it says which it did.
#include <cstdio>

#include "commands.h"
#include "game/sandbox.h"
#include "game/window.h"

namespace vox {

void addStartCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "start", "Open the sandbox if there is a display, else render headless to out/render.png");
    auto world = std::make_shared<std::string>();
    cmd->add_option("world", *world,
                    "World name (worlds/NAME.toml) or scene file; default: sandbox");
    cmd->callback([world, &exitCode] {
        std::string why = game::displayProblem();
        if (why.empty()) {
            std::printf("vox start: display found: opening the sandbox (vox play%s%s)\n",
                        world->empty() ? "" : " ", world->c_str());
            std::fflush(stdout);
            game::PlayOptions options;
            options.world = *world;
            exitCode = game::runPlay(options);
            return;
        }
        std::printf(
            "vox start: %s: rendering headless instead (vox render%s%s -o out/render.png)\n",
            why.c_str(), world->empty() ? "" : " ", world->c_str());
        std::fflush(stdout);
        RenderOptions options;
        options.world = *world;
        exitCode = runRender(options);
    });
}

}  // namespace vox
