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
#include "world/region_store.h"
#include "world/world_info.h"

namespace vox {

namespace {

// The store's own figures: regions, compression, size on disk (docs/WORLD_STORE.md).
engine::Status printStoreInfo(const std::string& path) {
    auto store = engine::world::RegionStore::open(path, /*writable=*/false);
    if (!store) return store.error();
    auto rows = store->listRegions();
    if (!rows) return rows.error();
    std::uint64_t raw = 0, stored = 0, largest = 0;
    for (const engine::world::RegionRow& r : *rows) {
        raw += r.rawBytes;
        stored += r.storedBytes;
        largest = std::max(largest, r.storedBytes);
    }
    const engine::world::RegionStoreInfo& i = store->info();
    const glm::ivec3 count =
        engine::world::regionCount((i.worldSizeInVoxels + 7) / 8, i.regionCells);
    std::printf(
        "store        %s: %zu of %d region(s) stored (%d^3 cells, %d voxels a side); %.2f MiB "
        "raw, %.2f MiB zstd (%.1fx), largest region %.1f KiB; %.2f MiB on disk; %llu commit(s)\n",
        path.c_str(), rows->size(), count.x * count.y * count.z, i.regionCells, i.regionCells * 8,
        double(raw) / (1 << 20), double(stored) / (1 << 20),
        stored ? double(raw) / double(stored) : 0.0, double(largest) / 1024.0,
        double(store->fileBytes()) / (1 << 20), static_cast<unsigned long long>(i.commits));
    return {};
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("info",
                                   "Describe a world (size, bricks, voxels, emitters, memory) or a "
                                   ".vdb/.vox file (contents, and what an import would make)");
    auto world = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto vdbOptions = std::make_shared<VdbCliOptions>();
    cmd->add_option(
        "world", *world,
        "World name (worlds/NAME.toml), scene file, world store (.db), .vdb or .vox file; "
        "default: sandbox");
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
        if (std::filesystem::path(*world).extension() == ".db" && !*json) {
            if (engine::Status s = printStoreInfo(*world); !s) {
                exitCode = fail(s.error());
                return;
            }
        }
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
