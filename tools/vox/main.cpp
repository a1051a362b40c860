// vox: the engine's command-line tool. `vox --help` lists the subcommands.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "commands.h"
#include "core/log.h"
#include "core/memory_budget.h"
#include "core/symbol_table_pages.h"
#include "generator_progress.h"
#include "gpu/texel_buffer_limit.h"
#include "io/vdb_import.h"
#include "io/vox_import.h"
#include "number_options.h"
#include "scene/scene_file.h"
#include "scene/store_world.h"

namespace vox {

namespace {

using engine::Status;

// A scene file is TOML text: a NUL byte in its first 4 KiB means something else was given.
Status checkLooksLikeText(const std::filesystem::path& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return {};  // loadSceneFile reports it
    char head[4096];
    const std::size_t n = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
    if (std::memchr(head, 0, n) == nullptr) return {};
    return engine::makeError(
        "{}: not a scene file (binary data; a TOML scene file, a .vdb or a .vox file was expected, "
        "told apart by the file's extension)",
        path.string());
}

}  // namespace

engine::Result<engine::world::Scene> loadWorld(const std::string& nameOrPath) {
    // A .vdb or .vox stands for itself: imported with the default options.
    const std::string ext = std::filesystem::path(nameOrPath).extension().string();
    if (ext == ".vdb") return engine::io::importVdb(nameOrPath);
    if (ext == ".vox") return engine::io::importVox(nameOrPath);
    // A world store is a whole world (docs/WORLD_STORE.md).
    if (ext == ".db") return engine::scene::loadWorldStore(nameOrPath);
    auto path = engine::scene::resolveWorldPath(nameOrPath.empty() ? "sandbox" : nameOrPath);
    if (!path) return path.error();
    // Anything else must be a scene file: say so for a binary file rather than report its bytes.
    if (engine::Status text = checkLooksLikeText(*path); !text) return text.error();
    return engine::scene::loadSceneFile(*path);
}

std::filesystem::path worldFileOf(const std::string& nameOrPath) {
    const std::string ext = std::filesystem::path(nameOrPath).extension().string();
    if (ext == ".vdb" || ext == ".vox" || ext == ".db") return nameOrPath;
    auto path = engine::scene::resolveWorldPath(nameOrPath.empty() ? "sandbox" : nameOrPath);
    return path ? *path : std::filesystem::path();
}

engine::Result<std::filesystem::path> resolvePathFile(const std::string& arg) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_regular_file(arg, ec)) return fs::path(arg);
    std::string file = arg + (fs::path(arg).extension() == ".toml" ? "" : ".toml");
    for (fs::path dir : {fs::path("worlds/paths"), fs::path(VOX_SOURCE_DIR) / "worlds/paths"}) {
        if (std::filesystem::is_regular_file(dir / file, ec)) return dir / file;
    }
    return engine::makeError(
        "--path {}: no such path file (not a file, and not found in worlds/paths/)", arg);
}

engine::Result<glm::uvec2> parseSize(const std::string& text, const char* option) {
    constexpr engine::NumberRange kSide = engine::wholeRange(1, 8192, "pixels");
    std::size_t x = text.find_first_of("xX");
    std::optional<double> w, h;
    if (x != std::string::npos) {
        w = engine::readNumber(std::string_view(text).substr(0, x));
        h = engine::readNumber(std::string_view(text).substr(x + 1));
    }
    if (!w || !h) return engine::makeError("{}: expected WIDTHxHEIGHT, got '{}'", option, text);
    for (auto [name, v] : {std::pair{"width", *w}, std::pair{"height", *h}}) {
        if (engine::Status ok = engine::checkNumber(name, v, kSide); !ok)
            return engine::makeError("{}: {}", option, ok.error().message);
    }
    return glm::uvec2(unsigned(*w), unsigned(*h));
}

engine::Result<glm::vec3> parseVec3(const std::string& text, const char* option,
                                    const engine::NumberRange& range) {
    glm::vec3 out(0.0f);
    std::string_view rest = text;
    for (int i = 0; i < 3; ++i) {
        std::size_t end = i < 2 ? rest.find(',') : rest.size();
        std::optional<double> v;
        if (end != std::string_view::npos) v = engine::readNumber(rest.substr(0, end));
        if (!v) return engine::makeError("{}: expected x,y,z, got '{}'", option, text);
        if (engine::Status ok = engine::checkNumber(std::string(1, "xyz"[i]), *v, range); !ok)
            return engine::makeError("{}: {}", option, ok.error().message);
        out[i] = float(*v);
        if (i < 2) rest = rest.substr(end + 1);
    }
    return out;
}

int fail(const engine::Error& error) {
    std::fprintf(stderr, "vox: %s\n", error.message.c_str());
    return 1;
}

}  // namespace vox

int main(int argc, char** argv) {
    engine::log::init();
    vox::showLongProgress();
    // libopenvdb's symbol tables were read once by the dynamic linker; 26 MB nobody reads again.
    engine::releaseSymbolTablePages();
    CLI::App app{
        "vox: voxel engine tool (play, edit, render, capture, inspect, compare, import, export and "
        "benchmark brick-grid worlds)",
        "vox"};
    app.require_subcommand(1);
    // Options of vox itself may also follow the subcommand (vox render --memory-budget 2048 …).
    app.fallthrough();
    app.add_option_function<double>(
           "--memory-budget",
           [](double mib) { engine::setMemoryBudgetBytes(std::uint64_t(mib * double(1 << 20))); },
           "MiB a world may take to build and show (CPU grid, GPU copy, frame buffers); default "
           "3/4 of "
           "physical memory or of ulimit -v")
        ->check(vox::numberIn(engine::closedRange(64.0, double(1 << 24), "MiB")));
    int exitCode = 0;
    vox::addStartCommand(app, exitCode);
    vox::addPlayCommand(app, exitCode);
    vox::addRenderCommand(app, exitCode);
    vox::addInfoCommand(app, exitCode);
    vox::addCompareCommand(app, exitCode);
    vox::addCaptureCommand(app, exitCode);
    vox::addExportCommand(app, exitCode);
    vox::addImportCommand(app, exitCode);
    vox::addJobCommand(app, exitCode);
    CLI::App* bench = app.add_subcommand("bench", "Benchmarks (results as CSV/JSON under out/)");
    bench->require_subcommand(1);
    vox::addBenchTraverseCommand(*bench, exitCode);
    vox::addBenchEmittersCommand(*bench, exitCode);
    vox::addBenchRestirCommand(*bench, exitCode);
    vox::addBenchLightsCommand(*bench, exitCode);
    vox::addBenchAccuracyCommand(*bench, exitCode);
    vox::addBenchSweepCommand(*bench, exitCode);
    vox::addBenchStabilityCommand(*bench, exitCode);
    vox::addBenchCacheCommand(*bench, exitCode);
    vox::addBenchFrameCommand(*bench, exitCode);
    vox::addBenchFlythroughCommand(*bench, exitCode);
    vox::addBenchDisplayCommand(*bench, exitCode);
    vox::addBenchSkyCommand(*bench, exitCode);
    try {
        app.parse(argc, argv);
    } catch (const engine::MemoryBudgetExceeded& e) {
        std::fprintf(stderr, "vox: %s\n", e.what());
        return 1;
    } catch (const engine::gpu::TexelBufferTooLarge& e) {
        std::fprintf(stderr, "vox: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(
            stderr,
            "vox: out of memory (budget %.0f MiB): the world or the image is too large for this "
            "machine; make it smaller\n",
            double(engine::memoryBudgetBytes()) / (1 << 20));
        return 1;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "vox: %s (see vox --help)\n", e.what());
        return 2;
    }
    return exitCode;
}
