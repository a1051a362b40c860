// Subcommands of `vox`. Each add*Command registers its options on the app and sets `exitCode`
// when it runs.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/number_check.h"
#include "lighting_options.h"
#include "world/scene.h"

namespace vox {

void addRenderCommand(CLI::App& app, int& exitCode);
void addPlayCommand(CLI::App& app, int& exitCode);
void addStartCommand(CLI::App& app, int& exitCode);
void addInfoCommand(CLI::App& app, int& exitCode);
void addCompareCommand(CLI::App& app, int& exitCode);
void addCaptureCommand(CLI::App& app, int& exitCode);
void addExportCommand(CLI::App& app, int& exitCode);
void addImportCommand(CLI::App& app, int& exitCode);
void addJobCommand(CLI::App& app, int& exitCode);
void addBenchTraverseCommand(CLI::App& bench, int& exitCode);
void addBenchEmittersCommand(CLI::App& bench, int& exitCode);
void addBenchRestirCommand(CLI::App& bench, int& exitCode);
void addBenchLightsCommand(CLI::App& bench, int& exitCode);
void addBenchAccuracyCommand(CLI::App& bench, int& exitCode);
void addBenchSweepCommand(CLI::App& bench, int& exitCode);
void addBenchStabilityCommand(CLI::App& bench, int& exitCode);
void addBenchCacheCommand(CLI::App& bench, int& exitCode);
void addBenchFrameCommand(CLI::App& bench, int& exitCode);
void addBenchFlythroughCommand(CLI::App& bench, int& exitCode);
void addBenchDisplayCommand(CLI::App& bench, int& exitCode);
void addBenchSkyCommand(CLI::App& bench, int& exitCode);

struct RenderOptions {
    std::string world;
    std::string camera;
    std::string pos, target;
    std::optional<float> fov;  // absent: the camera's
    std::string size = "640x360";
    std::string output = "out/render.png";
    std::string exr;
    float exposure = 1.0f;
    std::uint32_t frames = 1;
    float renderScale = 1.0f;  // render size as a fraction of --size (the display's)
    double time = 0.0;         // scene time in seconds: poses dynamic objects
    std::uint32_t spp = 64;
    std::string timings;
    LightingOptions lighting;
};
// `vox render`: renders one image headless; prints what it did, returns the exit code.
int runRender(const RenderOptions& options);

// Loads a world by name or path (a .vdb is imported with default options); an empty argument
// means the built-in default world.
engine::Result<engine::world::Scene> loadWorld(const std::string& nameOrPath);
// The file loadWorld reads for `nameOrPath` (empty if there is none), for the checks of
// command_files.h.
std::filesystem::path worldFileOf(const std::string& nameOrPath);
// A camera path argument: a file, or a name in worlds/paths/ ("sandbox_orbit" ->
// worlds/paths/sandbox_orbit.toml).
engine::Result<std::filesystem::path> resolvePathFile(const std::string& arg);
// "640x360" -> {640, 360}; an error names the option.
// Each number goes through the one number check (core/number_check.h): "--size: width must be
// positive, not -5 (1..8192 pixels)".
engine::Result<glm::uvec2> parseSize(const std::string& text, const char* option);
// The lighting's size for a display of `display` pixels at render scale `scale` (--render-scale):
// rounded, at least one pixel.
inline glm::uvec2 renderSizeOf(glm::uvec2 display, float scale) {
    return glm::max(glm::uvec2(1u), glm::uvec2(glm::round(glm::vec2(display) * scale)));
}
// "x,y,z", each component within `range`.
engine::Result<glm::vec3> parseVec3(const std::string& text, const char* option,
                                    const engine::NumberRange& range);
// --show-settings: loads the world, merges its lighting with the options and prints the result.
int showSettings(const std::string& world, const LightingOptions& options);
// One line on stderr, exit code 1.
int fail(const engine::Error& error);

}  // namespace vox
