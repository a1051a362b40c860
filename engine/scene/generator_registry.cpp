// The registry table. Each generator's keys live in engine/scene/generators/NAME_keys.cpp, not
// beside its algorithm in world/: reading a scene file is this layer's job (world/ knows no TOML
// and io/ is above it, yet the vdb generator is one of them), and keeping all of them here lets
// every entry use the same reader and writer. The algorithms stay in world/ (and io/ for vdb).
// CMake picks up every file in generators/, so a new generator is its own files plus one line in
// VOX_SCENE_GENERATORS below.
#include "scene/generator_registry.h"

#include "core/check.h"

namespace engine::scene {

// Order: how knownGeneratorTypes() lists them in messages.
#define VOX_SCENE_GENERATORS(X) \
    X(Terrain)                  \
    X(Box)                      \
    X(Sphere)                   \
    X(Cornell)                  \
    X(Buildings)                \
    X(Lamps)                    \
    X(Mountain)                 \
    X(ScatteredLights)          \
    X(Text)                     \
    X(Menger)                   \
    X(Apartment)                \
    X(Bridge)                   \
    X(Vdb)                      \
    X(Vox)                      \
    X(Store)

#define VOX_DECLARE_GENERATOR(Name) extern const GeneratorEntry k##Name##Generator;
#define VOX_LIST_GENERATOR(Name) &k##Name##Generator,
VOX_SCENE_GENERATORS(VOX_DECLARE_GENERATOR)

namespace {

const GeneratorEntry* const kGenerators[] = {VOX_SCENE_GENERATORS(VOX_LIST_GENERATOR)};

}  // namespace

world::MaterialId GeneratorKeys::material(std::string_view key, const char* fallback) {
    std::string name = string(key, fallback);
    if (name == "empty" || name == "air") return world::kEmpty;
    auto id = mScene.palette.find(name);
    if (!id) fail(node(key), "unknown material '{}'", name);
    return *id;
}

void GeneratorWriter::material(std::string_view key, world::MaterialId id) const {
    toml.key(key, id == world::kEmpty ? std::string("empty") : palette[id].name);
}

const GeneratorEntry* findGenerator(std::string_view type) {
    for (const GeneratorEntry* e : kGenerators) {
        if (e->type == type) return e;
    }
    return nullptr;
}

std::string knownGeneratorTypes() {
    std::string out;
    for (const GeneratorEntry* e : kGenerators)
        out += (out.empty() ? "" : ", ") + std::string(e->type);
    return out;
}

void writeGenerator(const world::GeneratorRecord& record, std::string_view table, TomlWriter& toml,
                    const world::Palette& palette) {
    const GeneratorEntry* entry = findGenerator(record.type);
    CHECK(entry);
    toml.arrayTable(table);
    toml.key("type", record.type);
    entry->write(record.params, GeneratorWriter{toml, palette});
}

}  // namespace engine::scene
