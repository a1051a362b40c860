// vox bench emitters: the emitter list's incremental update after a single-voxel edit against a
// full rebuild, on a large world with many emissive voxels (issue: cost follows the edit).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "commands.h"
#include "core/atomic_file.h"
#include "core/hash.h"
#include "lighting/emitter_list.h"
#include "number_options.h"
#include "world/generators.h"

namespace vox {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct EmitterBenchOptions {
    std::string world = "terrain_1024";
    int lights = 100000;
    int edits = 50;
    std::string output = "out/bench_emitters.json";
};

int runEmitterBench(const EmitterBenchOptions& o) {
    std::printf("loading world %s ...\n", o.world.c_str());
    auto scene = loadWorld(o.world);
    if (!scene) return fail(scene.error());
    auto lamp = scene->palette.add(
        engine::world::Material{"bench-lamp", glm::vec3(1.0f), glm::vec3(1.0f, 0.9f, 0.7f), 3.0f});
    if (!lamp) return fail(engine::makeError("palette full"));
    // Scatter single emissive voxels on the surface.
    engine::Rng rng(42);
    const glm::ivec3 size = scene->grid.sizeInVoxels();
    std::vector<glm::ivec3> placed;
    for (int i = 0; i < o.lights; ++i) {
        int x = rng.uniformInt(0, size.x - 1), z = rng.uniformInt(0, size.z - 1);
        int y = std::min(engine::world::groundHeight(scene->grid, x, z), size.y - 1);
        scene->grid.set({x, y, z}, *lamp);
        placed.push_back({x, y, z});
    }
    std::printf("world %d x %d x %d, %llu emissive voxels placed\n", size.x, size.y, size.z,
                static_cast<unsigned long long>(scene->emissiveVoxels()));

    engine::lighting::EmitterList list;
    std::vector<double> full;
    for (int i = 0; i < 3; ++i) {
        auto start = Clock::now();
        list.rebuild(*scene);
        full.push_back(msSince(start));
    }
    scene->grid.clearDirty();
    std::printf("full rebuild: %u emitters in %.2f ms (median of 3)\n", list.aliveCount(),
                median(full));

    std::vector<double> incremental, alias;
    std::uint32_t cells = 0;
    for (int i = 0; i < o.edits; ++i) {
        // Alternately remove a light and put it back: one voxel per edit.
        glm::ivec3 p = placed[std::size_t(rng.uniformInt(0, int(placed.size()) - 1))];
        bool remove = scene->grid.get(p) == *lamp;
        scene->grid.set(p, remove ? engine::world::kEmpty : *lamp);
        auto start = Clock::now();
        auto stats = list.update(*scene);
        incremental.push_back(msSince(start));
        start = Clock::now();
        list.aliasTable();
        alias.push_back(msSince(start));
        cells = std::max(cells, stats.cellsScanned);
        scene->grid.clearDirty();
    }
    double inc = median(incremental), fullMs = median(full);
    std::printf(
        "single-voxel edit: incremental update %.4f ms (median of %d, at most %u cells rescanned), "
        "%.0fx faster "
        "than a full rebuild\n",
        inc, o.edits, cells, fullMs / inc);
    std::printf("alias table rebuild after the edit (O(emitters), separate): %.3f ms\n",
                median(alias));

    std::filesystem::path out(o.output);
    std::error_code ec;
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
    engine::AtomicFile jsonFile;
    if (engine::Status s = jsonFile.open(out); !s) return fail(s.error());
    std::ostream& json = jsonFile.stream();
    json << "{\"world\": \"" << scene->name
         << "\", \"emissive_voxels\": " << scene->emissiveVoxels()
         << ", \"emitters\": " << list.aliveCount() << ", \"full_rebuild_ms\": " << fullMs
         << ", \"incremental_update_ms\": " << inc << ", \"speedup\": " << fullMs / inc
         << ", \"alias_rebuild_ms\": " << median(alias) << ", \"edits\": " << o.edits << "}\n";
    if (engine::Status s = jsonFile.commit(); !s) return fail(s.error());
    std::printf("wrote    %s\n", out.string().c_str());
    return 0;
}

}  // namespace

void addBenchEmittersCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "emitters", "Emitter list: incremental update after an edit vs full rebuild");
    auto o = std::make_shared<EmitterBenchOptions>();
    cmd->add_option("world", o->world, "World name or scene file")->capture_default_str();
    cmd->add_option("--lights", o->lights, "Emissive voxels to scatter on the surface")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 10000000, "voxels")));
    cmd->add_option("--edits", o->edits, "Single-voxel edits to time")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 100000, "edits")));
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runEmitterBench(*o); });
}

}  // namespace vox
