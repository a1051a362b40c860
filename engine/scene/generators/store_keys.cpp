// [[generator]] type = "store": the regions of a world store (scene/store_world.h), material ids
// mapped by name onto the palette above it. One key: source.
#include "scene/generators/store_keys.h"

#include "scene/generator_registry.h"
#include "scene/store_world.h"

namespace engine::scene {

namespace {

namespace fs = std::filesystem;

struct StoreParams {
    std::string source;  // as written: relative to the scene file's folder, or absolute
};

fs::path resolve(const StoreParams& p, const world::Scene& scene) {
    const fs::path source(p.source);
    return source.is_absolute() ? source : fs::path(scene.sourcePath).parent_path() / source;
}

StoreParams parse(GeneratorKeys& g) { return {g.string("source")}; }

Status run(const StoreParams& p, world::Scene& scene) {
    return readStoreInto(scene, resolve(p, scene));
}

void write(const StoreParams& p, const GeneratorWriter& out) { out.toml.key("source", p.source); }

}  // namespace

extern const GeneratorEntry kStoreGenerator =
    makeGeneratorEntry<StoreParams, parse, run, write>("store");

world::GeneratorRecord storeGenerator(std::string source) {
    return {"store", StoreParams{std::move(source)}};
}

fs::path storeOfScene(const world::Scene& scene) {
    if (scene.generators.size() != 1 || scene.generators[0].type != "store") return {};
    return resolve(std::any_cast<const StoreParams&>(scene.generators[0].params), scene);
}

}  // namespace engine::scene
