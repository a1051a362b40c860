#include <cstdio>
#include <filesystem>
#include <fmt/format.h>

#include "command_files.h"
#include "commands.h"
#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "io/vox_import.h"
#include "number_options.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"
#include "scene/store_world.h"
#include "scene/world_pair.h"
#include "vdb_options.h"
#include "world/world_info.h"

namespace vox {

namespace fs = std::filesystem;

namespace {

// The import by the input's extension: .vox through io/vox_import.h (--offset and
// --memory-budget apply), anything else as OpenVDB. Fills `text` with the report.
engine::Result<engine::world::Scene> importFile(const std::string& input,
                                                const engine::io::VdbImportOptions& options,
                                                std::string& text, std::uint64_t& peakBytes) {
    if (fs::path(input).extension() == ".vox") {
        engine::io::VoxImportOptions voxOptions;
        if (options.offset) voxOptions.offset = *options.offset;
        voxOptions.memoryBudgetBytes = options.memoryBudgetBytes;
        engine::io::VoxImportReport report;
        auto scene = engine::io::importVox(input, voxOptions, &report);
        if (scene) text = engine::io::formatVoxImportReport(report, /*planned=*/false);
        peakBytes = report.peakTrackedBytes;
        return scene;
    }
    engine::io::VdbImportReport report;
    auto scene = engine::io::importVdb(input, options, &report);
    if (scene) text = engine::io::formatVdbImportReport(report);
    peakBytes = report.peakTrackedBytes;
    return scene;
}

// WORLD.toml + WORLD.N.vdb: the scene file names the payload with a vdb generator, so the world
// stays editable as text (cameras, sky, more generators) while its voxels and palette live in
// the exact, compact .vdb. With -o WORLD.vdb only the payload is written.
// WORLD.db: the world store (docs/WORLD_STORE.md), written region by region. The input may also
// be a world (a scene file or a store): the conversion of an old TOML + VDB save.
int runStoreImport(const std::string& input, const std::string& output, int regionCells,
                   const VdbCliOptions& cli) {
    const std::string inExt = fs::path(input).extension().string();
    const bool isWorld = inExt != ".vdb" && inExt != ".vox";
    if (engine::Status s = checkCommandFiles(
            {{"the input", isWorld ? worldFileOf(input) : fs::path(input)}}, {{"-o", output}});
        !s)
        return fail(s.error());
    std::string reportText;
    std::uint64_t peakBytes = 0;
    engine::Result<engine::world::Scene> scene = engine::makeError("");
    if (isWorld) {
        scene = loadWorld(input);
    } else {
        auto options = toImportOptions(cli);
        if (!options) return fail(options.error());
        scene = importFile(input, *options, reportText, peakBytes);
    }
    if (!scene) return fail(scene.error());
    std::error_code ec;
    const fs::path out(output);
    if (out.has_parent_path()) fs::create_directories(out.parent_path(), ec);
    auto report = engine::scene::writeWorldStore(*scene, out, regionCells);
    if (!report) return fail(report.error());
    std::printf("%s %s\n%s", isWorld ? "converted" : "imported", input.c_str(), reportText.c_str());
    std::printf(
        "regions  %zu of %d^3 cells (%d voxels a side), %.2f MiB raw, %.2f MiB compressed "
        "(zstd), %.0f ms\n",
        report->regionsWritten, regionCells, regionCells * 8, double(report->rawBytes) / (1 << 20),
        double(report->storedBytes) / (1 << 20), report->encodeMs);
    std::printf("wrote    %s (%.2f MiB on disk)\n", output.c_str(),
                double(report->fileBytes) / (1 << 20));
    return 0;
}

int runImport(const std::string& input, const std::string& output, bool dryRun,
              const VdbCliOptions& cli, int regionCells) {
    auto options = toImportOptions(cli);
    if (!options) return fail(options.error());
    std::string reportText;
    std::uint64_t peakBytes = 0;
    fs::path out(output);
    const std::string ext = out.extension().string();
    if (dryRun) {
        auto scene = importFile(input, *options, reportText, peakBytes);
        if (!scene) return fail(scene.error());
        std::printf("imported %s (dry run: nothing written)\n%s", input.c_str(),
                    reportText.c_str());
        engine::world::WorldInfo info = engine::world::describeWorld(*scene);
        std::printf(
            "  world size   %.2f MiB in memory (%llu bytes; %llu bricks, %llu homogeneous cells); "
            "peak heap during import %.2f MiB\n",
            double(info.totalBytes()) / (1 << 20),
            static_cast<unsigned long long>(info.totalBytes()),
            static_cast<unsigned long long>(info.bricks),
            static_cast<unsigned long long>(info.homogeneousCells), double(peakBytes) / (1 << 20));
        return 0;
    }
    if (output.empty())
        return fail(engine::makeError(
            "{}: give -o WORLD.db, WORLD.toml or WORLD.vdb (or --dry-run)", input));
    if (ext == ".db") return runStoreImport(input, output, regionCells, cli);
    if (ext != ".toml" && ext != ".vdb")
        return fail(engine::makeError("-o {}: the file must end in .db, .toml or .vdb", output));
    // Anything but .vox is read as OpenVDB (whatever its name, as before the store); a world
    // (scene file or store) converts only to a store.
    if (const std::string inExt = fs::path(input).extension().string();
        inExt == ".toml" || inExt == ".db")
        return fail(engine::makeError(
            "{}: a world converts only to a store (-o WORLD.db); import takes .vdb or .vox",
            input));
    if (engine::Status s = checkCommandFiles({{"the input", input}}, {{"-o", output}}); !s)
        return fail(s.error());
    // A scene file is replaced only if vox wrote it (an import or a save): a hand-written one
    // may hold cameras, sky and generators nobody could restore.
    std::error_code ec;
    if (ext == ".toml" && fs::is_regular_file(out, ec) &&
        !engine::scene::sceneFileMarked(out, engine::scene::kImportMarker) &&
        !engine::scene::sceneFileMarked(out, engine::scene::kSaveMarker))
        return fail(engine::makeError(
            "{}: a scene file not written by vox import or vox play; refusing to replace it "
            "(give -o a new name)",
            output));

    auto scene = importFile(input, *options, reportText, peakBytes);
    if (!scene) return fail(scene.error());
    if (out.has_parent_path())
        fs::create_directories(out.parent_path(), ec);  // like every output of vox
    fs::path payload = out;
    if (ext == ".vdb") {
        if (engine::Status s = engine::io::exportVdb(*scene, payload); !s) return fail(s.error());
    } else {
        // Atomic as a pair (scene/world_pair.h): the payload gets a new name WORLD.N.vdb, so the
        // input and the previous import stay intact until the scene file naming it is in place;
        // then only the earlier payloads of this world go (never the input, nor a VDB sequence
        // it belongs to).
        auto text = [&](const std::string& payloadName) {
            payload = out.parent_path() / payloadName;
            std::vector<engine::world::GeneratorRecord> generators{
                engine::scene::vdbPayloadGenerator(payloadName, /*ids=*/false)};
            std::string comment = fmt::format(
                "{} from {}.\nVoxels and palette live in {} (voxengine's VDB layout, "
                "docs/VDB.md);\n"
                "a [[material]] defined here with the same name overrides the payload's.",
                engine::scene::kImportMarker, fs::path(input).filename().string(), payloadName);
            return engine::scene::sceneText(*scene,
                                            {.headerComment = comment, .generators = &generators});
        };
        if (engine::Status s =
                engine::scene::writeWorldPair(*scene, out, text, {.keep = {fs::path(input)}});
            !s)
            return fail(s.error());
    }
    std::printf("imported %s\n%s", input.c_str(), reportText.c_str());
    engine::world::WorldInfo info = engine::world::describeWorld(*scene);
    std::printf(
        "  world size   %.2f MiB in memory (%llu bricks, %llu homogeneous cells); peak heap during "
        "import %.2f MiB\n",
        double(info.totalBytes()) / (1 << 20), static_cast<unsigned long long>(info.bricks),
        static_cast<unsigned long long>(info.homogeneousCells), double(peakBytes) / (1 << 20));
    if (ext == ".toml")
        std::printf("wrote    %s and %s\n", output.c_str(), payload.string().c_str());
    else
        std::printf("wrote    %s\n", payload.string().c_str());
    return 0;
}

}  // namespace

void addImportCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "import",
        "Import an OpenVDB (.vdb) or MagicaVoxel (.vox) file as a world: a world store (-o W.db) "
        "or a scene file + .vdb payload (-o W.toml). A world (scene file, old TOML + VDB save, "
        "store) given as the input converts to a store: vox import old.toml -o new.db");
    auto input = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    auto cli = std::make_shared<VdbCliOptions>();
    auto dryRun = std::make_shared<bool>(false);
    auto regionCells = std::make_shared<int>(engine::world::kRegionCells);
    cmd->add_option("input", *input,
                    "Input .vdb or .vox file (by extension), or a world to convert to a store")
        ->required();
    cmd->add_option("-o,--output", *output,
                    "WORLD.db (world store), WORLD.toml (scene file + WORLD.N.vdb payload) or "
                    "WORLD.vdb");
    cmd->add_option("--region-cells", *regionCells,
                    "With -o WORLD.db: region edge in 8^3 cells (for measurements; vox play "
                    "saves a store of another size whole)")
        ->check(numberIn(engine::wholeRange(1, 256, "cells")));
    cmd->add_flag("--dry-run", *dryRun,
                  "Import and report (sizes, colour error, memory) without writing anything");
    addVdbImportOptions(*cmd, *cli);
    cmd->callback(
        [=, &exitCode] { exitCode = runImport(*input, *output, *dryRun, *cli, *regionCells); });
}

}  // namespace vox
