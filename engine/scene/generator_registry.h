// The generator registry: one entry per [[generator]] type of a scene file, each reading and
// writing its own keys (pbrt-v4's Create() reading its own parameters, plus the way back).
//
// A scene file's generator table becomes a world::GeneratorRecord (its type and the entry's
// parameter struct); the entry runs it on the scene's grid and writes it back as keys, so a
// loaded scene can be saved without losing how it was built. Materials are named by the palette.
#pragma once

#include <any>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/toml_reader.h"
#include "scene/toml_writer.h"
#include "world/scene.h"
#include "world/world_limits.h"

namespace engine::scene {

// A generator table being read: its keys, and the scene it builds into (materials are looked up
// in its palette, some defaults follow its grid's size).
class GeneratorKeys : public KeyReader {
public:
    GeneratorKeys(std::string_view source, const toml::table& t, const world::Scene& scene)
        : KeyReader(source, t), mScene(scene) {}
    // A palette material by name; "empty" and "air" are kEmpty. No fallback: the key is required.
    world::MaterialId material(std::string_view key, const char* fallback = nullptr);
    const world::Scene& scene() const { return mScene; }

private:
    const world::Scene& mScene;
};

// A generator table being written: keys, with materials by their palette names.
struct GeneratorWriter {
    TomlWriter& toml;
    const world::Palette& palette;
    void material(std::string_view key, world::MaterialId id) const;
};

struct GeneratorEntry {
    std::string_view type;
    // Reads and checks the keys (failing through the reader); returns the parameter struct.
    std::any (*parse)(GeneratorKeys& keys);
    // Builds into scene.grid (a vdb payload may also extend the palette).
    Status (*run)(const std::any& params, world::Scene& scene);
    // Writes the keys after `type`, so that parse gives back the same parameters.
    void (*write)(const std::any& params, const GeneratorWriter& out);
};

// An entry from typed functions, for the generators' own files.
template <typename P, P (*Parse)(GeneratorKeys&), Status (*Run)(const P&, world::Scene&),
          void (*Write)(const P&, const GeneratorWriter&)>
constexpr GeneratorEntry makeGeneratorEntry(std::string_view type) {
    return {type, [](GeneratorKeys& keys) { return std::any(Parse(keys)); },
            [](const std::any& p, world::Scene& scene) {
                return Run(std::any_cast<const P&>(p), scene);
            },
            [](const std::any& p, const GeneratorWriter& out) {
                Write(std::any_cast<const P&>(p), out);
            }};
}

// The `run` of a generator that only writes the grid: world's generateX(grid, params).
template <typename P, auto Generate>
Status generateOnGrid(const P& params, world::Scene& scene) {
    Generate(scene.grid, params);
    return {};
}

// nullptr for a type no entry has.
const GeneratorEntry* findGenerator(std::string_view type);
// "terrain, box, ..." for messages.
std::string knownGeneratorTypes();

// Writes one [[generator]] (or [[object.generator]]: `table`) for `record`.
void writeGenerator(const world::GeneratorRecord& record, std::string_view table, TomlWriter& toml,
                    const world::Palette& palette);

}  // namespace engine::scene
