#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "core/memory_budget.h"
#include "io/vdb_info.h"
#include "io/vox_import.h"
#include "render/irradiance_cache/irradiance_cache.h"
#include "render/memory_plan.h"
#include "scene/scene_lighting.h"
#include "shared/brick_grid.h"
#include "vdb_options.h"
#include "world/world_info.h"

namespace vox {

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("info",
                                   "Describe a world (size, bricks, voxels, emitters, memory) or a "
                                   ".vdb/.vox file (contents, and what an import would make)");
    auto world = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto vdbOptions = std::make_shared<VdbCliOptions>();
    cmd->add_option(
        "world", *world,
        "World name (worlds/NAME.toml), scene file, .vdb or .vox file; default: sandbox");
    cmd->add_flag("--json", *json, "Print JSON instead of text (worlds)");
    addVdbImportOptions(*cmd, *vdbOptions);
    cmd->callback([=, &exitCode] {
        if (std::filesystem::path(*world).extension() == ".vox") {
            auto options = toImportOptions(*vdbOptions);
            if (!options) {
                exitCode = fail(options.error());
                return;
            }
            engine::io::VoxImportOptions voxOptions;
            if (options->offset) voxOptions.offset = *options->offset;
            voxOptions.memoryBudgetBytes = options->memoryBudgetBytes;
            auto plan = engine::io::planVoxImport(*world, voxOptions);
            if (!plan) {
                exitCode = fail(plan.error());
                return;
            }
            std::printf("file         %s\n%s", world->c_str(),
                        engine::io::formatVoxImportReport(*plan, /*planned=*/true).c_str());
            return;
        }
        if (std::filesystem::path(*world).extension() == ".vdb") {
            auto options = toImportOptions(*vdbOptions);
            if (!options) {
                exitCode = fail(options.error());
                return;
            }
            auto info = engine::io::describeVdbFile(*world, *options);
            if (!info) {
                exitCode = fail(info.error());
                return;
            }
            std::printf("%s", engine::io::formatVdbFileInfo(*info).c_str());
            return;
        }
        // --memory-budget applies to a world too.
        if (auto options = toImportOptions(*vdbOptions); !options) {
            exitCode = fail(options.error());
            return;
        }
        auto scene = loadWorld(*world);
        if (!scene) {
            exitCode = fail(scene.error());
            return;
        }
        engine::world::WorldInfo info = engine::world::describeWorld(*scene);
        if (*json) {
            std::printf("%s\n", engine::world::worldInfoJson(info).c_str());
            return;
        }
        std::printf(
            "%s", engine::world::formatWorldInfo(info, scene->name + " (" + scene->sourcePath + ")")
                      .c_str());
        std::uint64_t pages = (info.bricks + info.freeBricks + shared::BRICK_PAGE_BRICKS - 1) /
                              shared::BRICK_PAGE_BRICKS;
        std::printf(
            "gpu          %llu brick page(s) of %u bricks (%.2f MiB each), top grid and palette as "
            "above\n",
            static_cast<unsigned long long>(std::max<std::uint64_t>(pages, 1)),
            shared::BRICK_PAGE_BRICKS, double(shared::BRICK_PAGE_WORDS) * 4.0 / (1 << 20));
        // The cache's memory follows what the camera sees, not the world: state its rate and bound.
        auto lighting = engine::scene::lightingFor(&*scene, {});
        if (!lighting) {
            exitCode = fail(lighting.error());
            return;
        }
        // The peak of showing it, at the sandbox's window size (vox render and capture scale the
        // frame part with --size); the renderer refuses a world over the budget before allocating.
        const engine::render::MemoryPlan plan =
            engine::render::planMemory(*scene, {1280, 720}, *lighting);
        std::printf("peak         %s%s\n",
                    engine::render::formatMemoryPlan(plan, engine::memoryBudgetBytes()).c_str(),
                    plan.total() > engine::memoryBudgetBytes() ? " — OVER BUDGET" : "");
        const engine::lighting::IrradianceCacheSettings& cache = lighting->cache;
        const std::uint64_t perVoxel = engine::render::IrradianceCache::bytesPerSlot(cache);
        std::printf(
            "indirect     %s; irradiance cache %.2f KiB per visible surface voxel (K=%u), budget "
            "%.0f MiB = %llu voxels\n",
            engine::lighting::indirectName(lighting->indirect), double(perVoxel) / 1024.0,
            cache.directions, double(cache.budgetBytes) / 1048576.0,
            static_cast<unsigned long long>(cache.budgetBytes / perVoxel));
    });
}

}  // namespace vox
