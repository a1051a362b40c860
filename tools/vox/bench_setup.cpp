#include "bench_setup.h"

#include "commands.h"
#include "gpu/context.h"

namespace vox {

engine::Result<engine::render::FrameSettings> frameOfSize(const std::string& size,
                                                          const char* option) {
    auto parsed = parseSize(size, option);
    if (!parsed) return parsed.error();
    engine::render::FrameSettings frame;
    frame.width = parsed->x;
    frame.height = parsed->y;
    return frame;
}

engine::Result<BenchSetup> openBench(const std::string& size) {
    auto frame = frameOfSize(size);
    if (!frame) return frame.error();
    auto gpu = createBenchGpu();
    if (!gpu) return gpu.error();
    return BenchSetup{std::move(*gpu), *frame};
}

engine::Result<std::vector<engine::world::Scene>> loadWorlds(
    const std::vector<std::string>& names) {
    std::vector<engine::world::Scene> scenes;
    for (const std::string& name : names) {
        auto scene = loadWorld(name);
        if (!scene) return scene.error();
        scenes.push_back(std::move(*scene));
    }
    return scenes;
}

engine::Status openOutputFile(engine::AtomicFile& file, const std::filesystem::path& path) {
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    return file.open(path);
}

}  // namespace vox
