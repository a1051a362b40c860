#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "command_files.h"
#include "commands.h"
#include "io/vdb_export.h"
#include "io/vox_export.h"
#include "scene/store_world.h"
#include "scene/world_regions.h"

namespace vox {

namespace {

int writeVox(const engine::world::Scene& scene, const std::string& output) {
    std::error_code ec;
    const std::filesystem::path out(output);
    if (out.has_parent_path())
        std::filesystem::create_directories(out.parent_path(), ec);  // like every output of vox
    engine::io::VoxExportReport r;
    if (engine::Status s = engine::io::exportVox(scene, out, &r); !s) return fail(s.error());
    std::printf("wrote    %s (%.2f MiB)\nmodels   %zu of at most 256^3\nvoxels   %llu solid\n",
                output.c_str(), double(r.fileBytes) / (1 << 20), r.models,
                static_cast<unsigned long long>(r.solidVoxels));
    std::printf("palette  %d colour(s), %d emissive (MATL _emit)", r.colours, r.emissive);
    if (r.quantised)
        std::printf(
            "; more than 255 colours, quantised: %llu voxels changed, colour error mean %.4f, max "
            "%.4f (linear RGB distance)",
            static_cast<unsigned long long>(r.changedVoxels), r.meanColourError, r.maxColourError);
    else
        std::printf("; exact");
    std::printf("\n");
    if (r.emissionColourDiffers)
        std::printf(
            "note     %llu emissive voxels emit a colour other than their albedo; .vox emits the "
            "albedo\n",
            static_cast<unsigned long long>(r.emissionColourDiffers));
    return 0;
}

// From `regions` when given (the scene's grid is then not read), else from the scene's grid.
int writeVdb(const engine::world::Scene& scene, engine::world::RegionSource* regions,
             const engine::io::VdbExportOptions& options, const std::string& output) {
    engine::io::VdbExportReport report;
    std::error_code ec;
    const std::filesystem::path out(output);
    if (out.has_parent_path())
        std::filesystem::create_directories(out.parent_path(), ec);  // like every output of vox
    engine::Status s = regions ? engine::io::exportVdb(scene, *regions, out, options, &report)
                               : engine::io::exportVdb(scene, out, options, &report);
    if (!s) return fail(s.error());
    std::string grids;
    for (const auto& g : report.grids) grids += (grids.empty() ? "" : ", ") + g;
    std::printf(
        "wrote    %s (%.2f MiB)\ngrids    %s%s\nvoxels   %llu solid: %llu cells as 8^3 tiles, "
        "%llu bricks as leaves\n",
        output.c_str(), double(report.fileBytes) / (1 << 20), grids.c_str(),
        options.zUp ? "\naxes     Z-up (the engine's +y is the file's +z)" : "",
        static_cast<unsigned long long>(report.solidVoxels),
        static_cast<unsigned long long>(report.tiles),
        static_cast<unsigned long long>(report.leaves));
    if (regions)
        std::printf("read     region by region (%llu region reads), never the whole world\n",
                    static_cast<unsigned long long>(report.regionLoads));
    return 0;
}

}  // namespace

void addExportCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("export",
                                   "Export a world to OpenVDB (.vdb: material ids, albedo, "
                                   "emission, palette) or MagicaVoxel (.vox)");
    auto world = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    auto idsOnly = std::make_shared<bool>(false);
    cmd->add_option("world", *world,
                    "World name (worlds/NAME.toml), scene file, world store (.db) or .vdb")
        ->required();
    cmd->add_option("-o,--output", *output,
                    "Output .vdb or .vox file (the extension decides the format)")
        ->required();
    auto tool = std::make_shared<std::string>();
    auto box = std::make_shared<std::string>();
    cmd->add_option("--box", *box,
                    "x0,y0,z0,x1,y1,z1: export only this box of a world store (.db), reading only "
                    "the regions that meet it (rounded out to whole 8^3 cells)");
    cmd->add_flag("--ids-only", *idsOnly,
                  "Write only the material grid (no albedo/emission grids for other tools)");
    cmd->add_option("--for", *tool,
                    "Also write a float 'density' fog grid for another tool: blender (and turn the "
                    "file Z-up) or "
                    "houdini (Y-up)");
    cmd->callback([=, &exitCode] {
        const std::string ext = std::filesystem::path(*output).extension().string();
        if (ext != ".vdb" && ext != ".vox") {
            exitCode = fail(engine::makeError("-o {}: the file must end in .vdb or .vox", *output));
            return;
        }
        if (engine::Status s =
                checkCommandFiles({{"the world", worldFileOf(*world)}}, {{"-o", *output}});
            !s) {
            exitCode = fail(s.error());
            return;
        }
        std::optional<engine::world::Box> exportBox;
        if (!box->empty()) {
            int v[6];
            char extra;
            if (std::sscanf(box->c_str(), "%d,%d,%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &v[4],
                            &v[5], &extra) != 6) {
                exitCode =
                    fail(engine::makeError("--box: expected x0,y0,z0,x1,y1,z1, got '{}'", *box));
                return;
            }
            exportBox = engine::world::Box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
            if (exportBox->empty()) {
                exitCode = fail(engine::makeError(
                    "--box: the max corner must exceed the min corner on every axis"));
                return;
            }
            if (std::filesystem::path(*world).extension() != ".db") {
                exitCode =
                    fail(engine::makeError("--box: needs a world store (.db), not {}", *world));
                return;
            }
        }
        engine::io::VdbExportOptions options;
        if (ext == ".vdb" && !tool->empty()) {
            auto forTool = engine::io::vdbExportOptionsFor(*tool);
            if (!forTool) {
                exitCode = fail(engine::makeError("--for: {}", forTool.error().message));
                return;
            }
            options = *forTool;
        }
        options.colourGrids = !*idsOnly;
        // A store, or a terrain too wide to load whole, goes to VDB region by region. Anything
        // else (or a scene whose store has another palette) is loaded whole, as before: a
        // terrain region by region is generated once per pass (3x the time).
        if (ext == ".vdb" && !exportBox) {
            const std::filesystem::path file = worldFileOf(*world);
            if (file.extension() == ".db" || file.extension() == ".toml")
                if (auto lean = engine::scene::loadWorldLean(file))
                    if (auto regions = engine::scene::worldRegionsOf(*lean, file);
                        regions && regions->source &&
                        (!regions->store.empty() ||
                         std::max(lean->grid.sizeInVoxels().x, lean->grid.sizeInVoxels().z) >
                             engine::scene::kLoadWholeUpToVoxels)) {
                        exitCode = writeVdb(*lean, regions->source.get(), options, *output);
                        return;
                    }
        }
        auto scene =
            exportBox ? engine::scene::loadWorldStore(*world, exportBox) : loadWorld(*world);
        if (!scene) {
            exitCode = fail(scene.error());
            return;
        }
        exitCode =
            ext == ".vox" ? writeVox(*scene, *output) : writeVdb(*scene, nullptr, options, *output);
    });
}

}  // namespace vox
