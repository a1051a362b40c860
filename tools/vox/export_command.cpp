#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "io/vdb_export.h"

namespace vox {

void addExportCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("export", "Export a world to OpenVDB (.vdb): material ids, albedo, emission, palette");
    auto world = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    auto idsOnly = std::make_shared<bool>(false);
    cmd->add_option("world", *world, "World name (worlds/NAME.toml), scene file or .vdb")->required();
    cmd->add_option("-o,--output", *output, "Output .vdb file")->required();
    auto tool = std::make_shared<std::string>();
    cmd->add_flag("--ids-only", *idsOnly, "Write only the material grid (no albedo/emission grids for other tools)");
    cmd->add_option("--for", *tool,
                    "Also write a float 'density' fog grid for another tool: blender (and turn the file Z-up) or "
                    "houdini (Y-up)");
    cmd->callback([=, &exitCode] {
        if (std::filesystem::path(*output).extension() != ".vdb") {
            exitCode = fail(engine::makeError("-o {}: the file must end in .vdb", *output));
            return;
        }
        auto scene = loadWorld(*world);
        if (!scene) {
            exitCode = fail(scene.error());
            return;
        }
        engine::io::VdbExportOptions options;
        if (!tool->empty()) {
            auto forTool = engine::io::vdbExportOptionsFor(*tool);
            if (!forTool) {
                exitCode = fail(engine::makeError("--for: {}", forTool.error().message));
                return;
            }
            options = *forTool;
        }
        options.colourGrids = !*idsOnly;
        engine::io::VdbExportReport report;
        std::error_code ec;
        const std::filesystem::path out(*output);
        if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);  // like every output of vox
        engine::Status s = engine::io::exportVdb(*scene, out, options, &report);
        if (!s) {
            exitCode = fail(s.error());
            return;
        }
        std::string grids;
        for (const auto& g : report.grids) grids += (grids.empty() ? "" : ", ") + g;
        std::printf("wrote    %s (%.2f MiB)\ngrids    %s%s\nvoxels   %llu solid: %llu cells as 8^3 tiles, %llu bricks as leaves\n",
                    output->c_str(), double(report.fileBytes) / (1 << 20), grids.c_str(),
                    options.zUp ? "\naxes     Z-up (the engine's +y is the file's +z)" : "",
                    static_cast<unsigned long long>(report.solidVoxels), static_cast<unsigned long long>(report.tiles),
                    static_cast<unsigned long long>(report.leaves));
    });
}

}  // namespace vox
