// [[generator]] type = "vox": a MagicaVoxel file through io/vox_import.h, its visible models
// placed by the file's scene graph. Keys: source (relative to the scene file's folder, or
// absolute), offset (where the content's lowest corner lands; default 0,0,0), memory_budget_mib.
#include <filesystem>

#include "io/vox_import.h"
#include "scene/generator_registry.h"

namespace engine::scene {

namespace {

struct VoxParams {
    std::string source;
    io::VoxImportOptions options;
};

VoxParams parse(GeneratorKeys& g) {
    VoxParams p;
    p.source = g.string("source");
    p.options.offset = g.ivec3("offset", p.options.offset, kVoxelIndexRange);
    int budget = g.integer("memory_budget_mib", int(p.options.memoryBudgetBytes >> 20),
                           wholeRange(1, 1 << 24, "MiB"));
    p.options.memoryBudgetBytes = std::uint64_t(budget) << 20;
    return p;
}

Status run(const VoxParams& p, world::Scene& scene) {
    namespace fs = std::filesystem;
    fs::path path = fs::path(p.source).is_absolute()
                        ? fs::path(p.source)
                        : fs::path(scene.sourcePath).parent_path() / p.source;
    return io::importVoxInto(scene, path, p.options);
}

void write(const VoxParams& p, const GeneratorWriter& out) {
    const io::VoxImportOptions defaults;
    out.toml.key("source", p.source);
    if (p.options.offset != defaults.offset) out.toml.key("offset", p.options.offset);
    if (p.options.memoryBudgetBytes != defaults.memoryBudgetBytes)
        out.toml.key("memory_budget_mib", int(p.options.memoryBudgetBytes >> 20));
}

}  // namespace

extern const GeneratorEntry kVoxGenerator = makeGeneratorEntry<VoxParams, parse, run, write>("vox");

}  // namespace engine::scene
