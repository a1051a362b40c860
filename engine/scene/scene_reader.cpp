// The scene file reader of scene/scene_file.h: the tables in file order, generators through the
// registry (scene/generator_registry.h), [indirect] through scene/indirect_keys.h and [path]
// through scene/path_file.h.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/allocation_budget.h"
#include "core/memory_budget.h"
#include "lighting/lighting_knobs.h"
#include "scene/generator_registry.h"
#include "scene/indirect_keys.h"
#include "scene/path_table.h"
#include "scene/scene_file.h"
#include "scene/toml_reader.h"
#include "world/dynamic_grid.h"

namespace engine::scene {

namespace {

// Runs a generator within the memory budget less what the world holds already, so a world too
// large for the machine fails with one line instead of aborting in an allocation. Importers
// (vdb, vox) plan and budget their own reading.
Status runWithinBudget(const GeneratorEntry& entry, const world::GeneratorRecord& record,
                       world::Scene& scene) {
    if (entry.type == "vdb" || entry.type == "vox") return entry.run(record.params, scene);
    const std::uint64_t budget = memoryBudgetBytes();
    const world::GridMemory m = scene.grid.memory();
    const std::uint64_t held =
        m.topGridBytes + m.superGridBytes + m.brickPoolBytes + m.bookkeepingBytes;
    const std::uint64_t left = budget > held ? budget - held : 0;
    try {
        AllocationBudget allocations(left, left);
        AllocationBudget::LargeAllocations large;
        return entry.run(record.params, scene);
    } catch (const std::bad_alloc&) {
        return makeError(
            "generator '{}' needs more memory than the budget of {:.0f} MiB allows (the world held "
            "{:.0f} "
            "MiB before it): make the world smaller, or {}",
            entry.type, double(budget) / (1 << 20), double(held) / (1 << 20),
            memoryBudgetAdvice(budget));
    }
}

using world::Scene;

class SceneReader {
public:
    SceneReader(std::string source, const SceneLoadOptions& options)
        : mSource(std::move(source)), mOptions(options) {}

    template <typename... Args>
    [[noreturn]] void fail(const toml::node* at, fmt::format_string<Args...> f,
                           Args&&... args) const {
        scene::fail(mSource, at, f, std::forward<Args>(args)...);
    }

    Scene read(const toml::table& root) {
        Scene scene;
        scene.sourcePath = mSource;
        KeyReader top(mSource, root);
        readWorld(top, scene);
        for (const toml::node& m : arrayOfTables(top, "material")) readMaterial(m, scene);
        for (const toml::node& g : arrayOfTables(top, "generator"))
            readGenerator(g, scene, scene.generators);
        for (const toml::node& o : arrayOfTables(top, "object")) readObject(o, scene);
        for (const toml::node& c : arrayOfTables(top, "camera")) readCamera(c, scene);
        if (const toml::node* n = top.node("sky")) readSky(*n, scene);
        if (const toml::node* n = top.node("indirect")) {
            const toml::table* t = n->as_table();
            if (!t) fail(n, "'indirect' must be a table");
            KeyReader keys(mSource, *t);
            readIndirect(keys, *n, scene);
        }
        if (const toml::node* n = top.node("path")) {
            const toml::table* t = n->as_table();
            if (!t) fail(n, "'path' must be a table ([path])");
            scene.path = std::make_shared<const world::Flythrough>(readPath(*t, mSource));
        }
        scene.grid.clearDirty();
        world::updateDynamicObjects(scene.objects, scene.dynamic, 0.0, 0.0);
        top.finish();
        return scene;
    }

private:
    // [[name]] tables; none when the key is absent.
    const toml::array& arrayOfTables(KeyReader& top, std::string_view name) {
        static const toml::array kNone;
        const toml::node* n = top.node(name);
        if (!n) return kNone;
        const toml::array* a = n->as_array();
        if (!a) fail(n, "'{}' must be an array of tables ([[{}]])", name, name);
        return *a;
    }

    void readWorld(KeyReader& top, Scene& scene) {
        const toml::node* n = top.node("world");
        if (!n || !n->as_table()) fail(&top.raw(), "missing [world] table");
        KeyReader keys(mSource, *n->as_table());
        // Without a name, the file's own: two unnamed worlds must not share a default save.
        const std::string stem = std::filesystem::path(mSource).stem().string();
        scene.name = keys.string("name", stem.empty() ? "untitled" : stem.c_str());
        scene.voxelSize =
            static_cast<float>(keys.number("voxel_size", 1.0, world::kVoxelSizeRange));
        glm::ivec3 size =
            keys.ivec3("size", {}, wholeRange(1, world::kMaxWorldExtent, "voxels"), true);
        glm::u64vec3 cells = glm::u64vec3((size + 7) / 8);
        if (cells.x * cells.y * cells.z > world::kMaxSceneTopGridCells)
            fail(keys.node("size"),
                 "world size {}x{}x{} needs {} top-grid cells, more than the limit of {}", size.x,
                 size.y, size.z, cells.x * cells.y * cells.z, world::kMaxSceneTopGridCells);
        scene.grid = world::BrickGrid(size);
    }

    void readMaterial(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[material]] must be a table");
        KeyReader m(mSource, *t);
        world::Material mat;
        mat.name = m.string("name");
        if (scene.palette.find(mat.name)) fail(&node, "material '{}' is defined twice", mat.name);
        mat.albedo = m.vec3("albedo", mat.albedo, world::kAlbedoRange);
        mat.emissionColor = m.vec3("emission", glm::vec3(1.0f), world::kRadianceRange);
        mat.emissionStrength = static_cast<float>(m.number("strength", 0.0, world::kRadianceRange));
        if (!mat.emissive()) {
            mat.emissionColor = glm::vec3(0.0f);
            mat.emissionStrength = 0.0f;
        }
        if (!scene.palette.add(mat))
            fail(&node, "too many materials (at most {})", world::kMaxMaterials - 1);
    }

    // Parses one generator table through the registry, runs it on scene.grid and records it.
    void readGenerator(const toml::node& node, Scene& scene,
                       std::vector<world::GeneratorRecord>& records) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[generator]] must be a table");
        GeneratorKeys g(mSource, *t, scene);
        std::string type = g.string("type");
        if (type == "bricks") {
            // Saves by vox play before it wrote .vdb; the reader is gone (docs/SANDBOX.md says
            // how to convert one).
            fail(g.node("type"),
                 "generator 'bricks' (the .bricks payload of older vox play saves) is no longer "
                 "supported; "
                 "saves are .vdb now (docs/SANDBOX.md, Saves)");
        }
        const GeneratorEntry* entry = findGenerator(type);
        if (!entry)
            fail(g.node("type"), "unknown generator '{}' (known: {})", type, knownGeneratorTypes());
        world::GeneratorRecord record{type, entry->parse(g)};
        const bool streamed = !mOptions.gridGenerators && &records == &scene.generators;
        if (Status s = streamed ? Status{} : runWithinBudget(*entry, record, scene); !s)
            fail(&node, "{}", s.error().message);
        records.push_back(std::move(record));
    }

    // A dynamic object (world/dynamic_object.h): its model is built by [[object.generator]]
    // tables, the same generators as the world's, run on the model's own grid in model
    // coordinates; [[object.key]] tables are its path.
    void readObject(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[object]] must be a table");
        KeyReader o(mSource, *t);
        world::DynamicObject object;
        object.name = o.string("name", "object");
        object.modelSize =
            o.ivec3("size", {}, wholeRange(1, world::kMaxObjectExtent, "voxels"), true);
        world::BrickGrid model(object.modelSize);

        const toml::node* gens = o.node("generator");
        const toml::array* ga = gens ? gens->as_array() : nullptr;
        if (!ga || ga->empty())
            fail(gens ? gens : &node,
                 "object '{}' needs at least one [[object.generator]] for its model", object.name);
        // The generators write scene.grid: lend them the model's grid for the while.
        std::swap(scene.grid, model);
        try {
            for (const toml::node& g : *ga) readGenerator(g, scene, object.generators);
        } catch (...) {
            std::swap(scene.grid, model);
            throw;
        }
        std::swap(scene.grid, model);
        model.clearDirty();
        if (model.solidVoxels() == 0)
            fail(gens, "object '{}': its generators leave the model empty", object.name);
        object.model = std::make_shared<const world::BrickGrid>(std::move(model));

        bool loop = o.boolean("loop", true);
        const toml::node* keys = o.node("key");
        const toml::array* ka = keys ? keys->as_array() : nullptr;
        if (!ka || ka->empty())
            fail(keys ? keys : &node, "object '{}' needs at least one [[object.key]]", object.name);
        std::vector<world::ObjectKey> path;
        for (const toml::node& kn : *ka) path.push_back(readObjectKey(kn, path));
        if (loop && path.size() < 2) fail(keys, "a looping path needs at least two keys");
        object.path = world::ObjectPath(std::move(path), loop);
        scene.objects.push_back(std::move(object));
    }

    world::ObjectKey readObjectKey(const toml::node& kn,
                                   const std::vector<world::ObjectKey>& previous) {
        using Given = world::ObjectKey::Given;
        const toml::table* kt = kn.as_table();
        if (!kt) fail(&kn, "each [[object.key]] must be a table");
        KeyReader k(mSource, *kt);
        world::ObjectKey key;
        if (!k.has("time")) fail(&kn, "key: missing 'time'");
        key.time = k.number("time", 0.0, closedRange(-1e7, 1e7, "s"));
        if (!previous.empty() && !(key.time > previous.back().time))
            fail(k.node("time"), "key times must increase ({} follows {})", key.time,
                 previous.back().time);
        key.position = glm::dvec3(k.vec3("position", {}, world::kCoordinateRange, true));
        if (k.has("rotation") && (k.has("axis") || k.has("angle")))
            fail(&kn, "key: give 'rotation' or 'axis' and 'angle', not both");
        if (k.has("rotation")) {
            key.given = Given::YawPitchRoll;
            key.angles = glm::dvec3(k.vec3("rotation", {}, closedRange(-1e6, 1e6, "degrees")));
            key.rotation = world::rotationFromYawPitchRoll(key.angles);
        } else if (k.has("axis") || k.has("angle")) {
            key.given = Given::AxisAngle;
            key.angles = glm::dvec3(k.vec3("axis", {0.0f, 1.0f, 0.0f}, closedRange(-1e6, 1e6)));
            if (glm::length(key.angles) < 1e-9) fail(k.node("axis"), "'axis' must not be zero");
            key.angle = k.number("angle", 0.0, closedRange(-1e6, 1e6, "degrees"));
            key.rotation = world::rotationFromAxisAngle(key.angles, key.angle);
        }
        k.finish();
        return key;
    }

    void readCamera(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[camera]] must be a table");
        KeyReader c(mSource, *t);
        world::CameraPreset cam;
        cam.name = c.string("name");
        cam.position = c.vec3("position", {}, world::kCoordinateRange, true);
        cam.target = c.vec3("target", {}, world::kCoordinateRange, true);
        cam.fovYDegrees = static_cast<float>(c.number("fov", 60.0, world::kFovRange));
        if (glm::length(cam.target - cam.position) < 1e-4f)
            fail(&node, "camera '{}': target equals position", cam.name);
        scene.cameras.push_back(cam);
    }

    void readSky(const toml::node& n, Scene& scene) {
        const toml::table* t = n.as_table();
        if (!t) fail(&n, "'sky' must be a table");
        KeyReader sky(mSource, *t);
        glm::vec3 dir = sky.vec3("sun_direction", scene.sky.sunDirection, world::kDirectionRange);
        if (glm::length(dir) < 1e-6f) fail(&n, "'sun_direction' must not be zero");
        // A unit vector (as a written-back scene holds) is kept as is: normalising it again can
        // move its last bits, and load -> write -> load would drift.
        scene.sky.sunDirection =
            std::abs(glm::length(dir) - 1.0f) > 1e-6f ? glm::normalize(dir) : dir;
        scene.sky.sunRadiance =
            sky.vec3("sun_radiance", scene.sky.sunRadiance, world::kRadianceRange);
        scene.sky.skyRadiance =
            sky.vec3("sky_radiance", scene.sky.skyRadiance, world::kRadianceRange);
        if (sky.has("sky_light")) {
            const toml::node* at = sky.node("sky_light");
            const lighting::Knob* knob = lighting::knobForOption("sky");
            lighting::LightingSettings s;
            if (Status ok = lighting::setKnob(*knob, s, sky.string("sky_light")); !ok)
                fail(at, "sky_light: {}", ok.error().message);
            scene.sky.lightMode = lighting::knobText(*knob, s);
        }
    }

    std::string mSource;
    SceneLoadOptions mOptions;
};

}  // namespace

Result<Scene> loadSceneText(std::string_view text, std::string_view sourceName,
                            const SceneLoadOptions& options) {
    return parseToml<Scene>(text, sourceName, [&](const toml::table& root) {
        return SceneReader(std::string(sourceName), options).read(root);
    });
}

Result<Scene> loadSceneFile(const std::filesystem::path& path, const SceneLoadOptions& options) {
    auto text = readTextFile(path, "scene file");
    if (!text) return text.error();
    return loadSceneText(*text, path.string(), options);
}

Result<std::filesystem::path> resolveWorldPath(std::string_view nameOrPath) {
    namespace fs = std::filesystem;
    fs::path direct(nameOrPath);
    std::error_code ec;
    if (fs::is_regular_file(direct, ec)) return direct;
    std::string file = std::string(nameOrPath) + (direct.extension() == ".toml" ? "" : ".toml");
    for (fs::path dir : {fs::path("worlds"), fs::path(VOX_SOURCE_DIR) / "worlds"}) {
        if (fs::is_regular_file(dir / file, ec)) return dir / file;
    }
    return makeError("{}: no such world (not a file, and not found in worlds/)", nameOrPath);
}

}  // namespace engine::scene
