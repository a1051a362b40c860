#include "world/scene_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>
#include <string>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "world/apartment_generator.h"
#include "world/bridge_generator.h"
#include "io/vdb_import.h"
#include "world/generators.h"
#include "world/menger_generator.h"
#include "world/mountain_generator.h"
#include "world/scattered_lights_generator.h"
#include "world/text_generator.h"
#include "world/world_edits.h"

namespace engine::world {

namespace {

struct ParseError {
    std::string message;
};

class SceneParser {
public:
    explicit SceneParser(std::string source) : mSource(std::move(source)) {}

    template <typename... Args>
    [[noreturn]] void fail(const toml::node* at, fmt::format_string<Args...> f, Args&&... args) const {
        std::string where = mSource;
        if (at && at->source().begin.line) where += fmt::format(":{}", at->source().begin.line);
        throw ParseError{where + ": " + fmt::format(f, std::forward<Args>(args)...)};
    }

    // Reads one table and insists every key in it was understood (catches typos).
    class Table {
    public:
        Table(const SceneParser& p, const toml::table& t) : mParser(p), mTable(t) {}
        ~Table() noexcept(false) {
            if (std::uncaught_exceptions()) return;
            for (auto&& [key, node] : mTable) {
                if (!mUsed.count(std::string(key.str())))
                    mParser.fail(&node, "unknown key '{}'", key.str());
            }
        }
        const toml::node* node(std::string_view key) {
            mUsed.insert(std::string(key));
            return mTable.get(key);
        }
        const toml::table& raw() const { return mTable; }
        bool has(std::string_view key) const { return mTable.contains(key); }

        double number(std::string_view key, double fallback) {
            const toml::node* n = node(key);
            if (!n) return fallback;
            if (auto v = n->value<double>()) return *v;
            mParser.fail(n, "'{}' must be a number", key);
        }
        int integer(std::string_view key, int fallback) {
            const toml::node* n = node(key);
            if (!n) return fallback;
            if (auto v = n->value<std::int64_t>()) {
                if (*v < -(1ll << 30) || *v > (1ll << 30)) mParser.fail(n, "'{}' is out of range", key);
                return static_cast<int>(*v);
            }
            mParser.fail(n, "'{}' must be an integer", key);
        }
        bool boolean(std::string_view key, bool fallback) {
            const toml::node* n = node(key);
            if (!n) return fallback;
            if (auto v = n->value<bool>()) return *v;
            mParser.fail(n, "'{}' must be true or false", key);
        }
        std::string string(std::string_view key, const char* fallback = nullptr) {
            const toml::node* n = node(key);
            if (!n) {
                if (!fallback) mParser.fail(&mTable, "missing '{}'", key);
                return fallback;
            }
            if (auto v = n->value<std::string>()) return *v;
            mParser.fail(n, "'{}' must be a string", key);
        }
        template <int N>
        glm::vec<N, double> vector(std::string_view key, glm::vec<N, double> fallback, bool required = false) {
            const toml::node* n = node(key);
            if (!n) {
                if (required) mParser.fail(&mTable, "missing '{}'", key);
                return fallback;
            }
            const toml::array* a = n->as_array();
            if (!a || a->size() != N) mParser.fail(n, "'{}' must be an array of {} numbers", key, N);
            glm::vec<N, double> out;
            for (int i = 0; i < N; ++i) {
                auto v = (*a)[i].value<double>();
                if (!v) mParser.fail(n, "'{}' must be an array of {} numbers", key, N);
                out[i] = *v;
            }
            return out;
        }
        glm::vec2 vec2(std::string_view key, glm::vec2 fallback, bool required = false) {
            return glm::vec2(vector<2>(key, glm::dvec2(fallback), required));
        }
        glm::ivec2 ivec2(std::string_view key, glm::ivec2 fallback, bool required = false) {
            glm::dvec2 v = vector<2>(key, glm::dvec2(fallback), required);
            if (glm::any(glm::notEqual(glm::floor(v), v)) || glm::any(glm::greaterThan(glm::abs(v), glm::dvec2(1 << 20))))
                mParser.fail(node(key), "'{}' must hold whole numbers of voxels", key);
            return glm::ivec2(v);
        }
        // An array of strings, e.g. windows = ["warm", "cool"].
        std::vector<std::string> strings(std::string_view key) {
            const toml::node* n = node(key);
            std::vector<std::string> out;
            if (!n) return out;
            const toml::array* a = n->as_array();
            if (!a) mParser.fail(n, "'{}' must be an array of strings", key);
            for (const toml::node& e : *a) {
                auto v = e.value<std::string>();
                if (!v) mParser.fail(n, "'{}' must be an array of strings", key);
                out.push_back(*v);
            }
            return out;
        }
        glm::vec3 vec3(std::string_view key, glm::vec3 fallback, bool required = false) {
            return glm::vec3(vector<3>(key, glm::dvec3(fallback), required));
        }
        glm::ivec3 ivec3(std::string_view key, glm::ivec3 fallback, bool required = false) {
            glm::dvec3 v = vector<3>(key, glm::dvec3(fallback), required);
            if (glm::any(glm::notEqual(glm::floor(v), v)) || glm::any(glm::greaterThan(glm::abs(v), glm::dvec3(1 << 20))))
                mParser.fail(node(key), "'{}' must hold whole numbers of voxels", key);
            return glm::ivec3(v);
        }

    private:
        const SceneParser& mParser;
        const toml::table& mTable;
        std::set<std::string> mUsed;
    };

    Scene parse(const toml::table& root) {
        Scene scene;
        scene.sourcePath = mSource;
        Table top(*this, root);
        parseWorld(top, scene);
        if (const toml::node* n = top.node("material")) {
            const toml::array* a = n->as_array();
            if (!a) fail(n, "'material' must be an array of tables ([[material]])");
            for (const toml::node& m : *a) parseMaterial(m, scene);
        }
        if (const toml::node* n = top.node("generator")) {
            const toml::array* a = n->as_array();
            if (!a) fail(n, "'generator' must be an array of tables ([[generator]])");
            for (const toml::node& g : *a) parseGenerator(g, scene);
        }
        if (const toml::node* n = top.node("object")) {
            const toml::array* a = n->as_array();
            if (!a) fail(n, "'object' must be an array of tables ([[object]])");
            for (const toml::node& o : *a) parseObject(o, scene);
        }
        if (const toml::node* n = top.node("camera")) {
            const toml::array* a = n->as_array();
            if (!a) fail(n, "'camera' must be an array of tables ([[camera]])");
            for (const toml::node& c : *a) parseCamera(c, scene);
        }
        if (const toml::node* n = top.node("sky")) {
            const toml::table* t = n->as_table();
            if (!t) fail(n, "'sky' must be a table");
            Table sky(*this, *t);
            glm::vec3 dir = sky.vec3("sun_direction", scene.sky.sunDirection);
            if (glm::length(dir) < 1e-6f) fail(n, "'sun_direction' must not be zero");
            scene.sky.sunDirection = glm::normalize(dir);
            scene.sky.sunRadiance = sky.vec3("sun_radiance", scene.sky.sunRadiance);
            scene.sky.skyRadiance = sky.vec3("sky_radiance", scene.sky.skyRadiance);
        }
        if (const toml::node* n = top.node("indirect")) parseIndirect(n, scene);
        // [path] (camera keys and events) is read by world/flythrough_file.h when a capture plays it.
        (void)top.node("path");
        scene.grid.clearDirty();
        updateDynamicObjects(scene.objects, scene.dynamic, 0.0, 0.0);
        return scene;
    }

private:
    void parseIndirect(const toml::node* n, Scene& scene) {
        const toml::table* t = n->as_table();
        if (!t) fail(n, "'indirect' must be a table");
        Table ind(*this, *t);
        if (const toml::node* mode = ind.node("mode")) {
            auto name = mode->value<std::string>();
            auto parsed = lighting::parseIndirect(name ? *name : "");
            if (!parsed) fail(mode, "indirect: {}", parsed.error().message);
            scene.indirect = *parsed;
        }
        lighting::IrradianceCacheSettings& c = scene.cache;
        auto count = [&](std::string_view key, std::uint32_t fallback) {
            int v = ind.integer(key, static_cast<int>(fallback));
            if (v < 0) fail(ind.node(key), "'{}' must not be negative", key);
            return static_cast<std::uint32_t>(v);
        };
        c.directions = count("directions", c.directions);
        c.raysPerUpdate = count("rays", c.raysPerUpdate);
        c.bounces = count("bounces", c.bounces);
        c.neighbourhood = count("neighbourhood", c.neighbourhood);
        c.alpha = static_cast<float>(ind.number("alpha", c.alpha));
        c.fadeSeconds = static_cast<float>(ind.number("fade", c.fadeSeconds));
        c.maxRayLength = static_cast<float>(ind.number("max_ray", c.maxRayLength));
        c.filter = ind.boolean("filter", c.filter);
        c.budgetBytes = static_cast<std::uint64_t>(ind.number("budget_mb", double(c.budgetBytes) / 1048576.0) * 1048576.0);
        if (Status s = lighting::validate(c); !s) fail(n, "indirect: {}", s.error().message);
    }

    void parseWorld(Table& top, Scene& scene) {
        const toml::node* n = top.node("world");
        if (!n || !n->as_table()) fail(&top.raw(), "missing [world] table");
        Table world(*this, *n->as_table());
        scene.name = world.string("name", "untitled");
        scene.voxelSize = static_cast<float>(world.number("voxel_size", 1.0));
        if (!(scene.voxelSize > 0.0f && scene.voxelSize <= 1e6f))
            fail(world.node("voxel_size"), "'voxel_size' must be in (0, 1e6]");
        glm::ivec3 size = world.ivec3("size", {}, true);
        if (glm::any(glm::lessThan(size, glm::ivec3(1))) || glm::any(glm::greaterThan(size, glm::ivec3(kMaxWorldExtent))))
            fail(world.node("size"), "world size {}x{}x{} is outside 1..{} voxels per axis", size.x, size.y, size.z,
                 kMaxWorldExtent);
        glm::u64vec3 cells = glm::u64vec3((size + 7) / 8);
        if (cells.x * cells.y * cells.z > kMaxTopGridCells)
            fail(world.node("size"), "world size {}x{}x{} needs {} top-grid cells, more than the limit of {}", size.x,
                 size.y, size.z, cells.x * cells.y * cells.z, kMaxTopGridCells);
        scene.grid = BrickGrid(size);
    }

    void parseMaterial(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[material]] must be a table");
        Table m(*this, *t);
        Material mat;
        mat.name = m.string("name");
        if (scene.palette.find(mat.name)) fail(&node, "material '{}' is defined twice", mat.name);
        mat.albedo = m.vec3("albedo", mat.albedo);
        mat.emissionColor = m.vec3("emission", glm::vec3(1.0f));
        mat.emissionStrength = static_cast<float>(m.number("strength", 0.0));
        if (glm::any(glm::lessThan(mat.albedo, glm::vec3(0.0f))) || glm::any(glm::greaterThan(mat.albedo, glm::vec3(1.0f))))
            fail(&node, "material '{}': albedo must lie in [0, 1]", mat.name);
        if (mat.emissionStrength < 0.0f || glm::any(glm::lessThan(mat.emissionColor, glm::vec3(0.0f))))
            fail(&node, "material '{}': emission must not be negative", mat.name);
        if (!mat.emissive()) {
            mat.emissionColor = glm::vec3(0.0f);
            mat.emissionStrength = 0.0f;
        }
        if (!scene.palette.add(mat)) fail(&node, "too many materials (at most {})", kMaxMaterials - 1);
    }

    MaterialId material(Table& t, const Scene& scene, std::string_view key, const char* fallback = nullptr) {
        std::string name = t.string(key, fallback);
        if (name == "empty" || name == "air") return kEmpty;
        auto id = scene.palette.find(name);
        if (!id) fail(t.node(key), "unknown material '{}'", name);
        return *id;
    }

    void parseGenerator(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[generator]] must be a table");
        Table g(*this, *t);
        std::string type = g.string("type");
        BrickGrid& grid = scene.grid;
        if (type == "terrain") {
            TerrainParams p;
            p.top = material(g, scene, "top");
            p.soil = material(g, scene, "soil");
            p.rock = material(g, scene, "rock");
            p.soilDepth = g.integer("soil_depth", p.soilDepth);
            p.baseHeight = static_cast<float>(g.number("base_height", p.baseHeight));
            p.amplitude = static_cast<float>(g.number("amplitude", p.amplitude));
            p.wavelength = static_cast<float>(g.number("wavelength", p.wavelength));
            p.octaves = g.integer("octaves", p.octaves);
            p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
            if (p.octaves < 1 || p.octaves > 12) fail(g.node("octaves"), "'octaves' must be in 1..12");
            generateTerrain(grid, p);
        } else if (type == "box") {
            Box box{g.ivec3("min", {}, true), g.ivec3("max", {}, true)};
            MaterialId m = material(g, scene, "material");
            int wall = g.integer("hollow_wall", 0);
            fillBox(grid, box, m);
            if (wall > 0) fillBox(grid, Box{box.min + wall, box.max - wall}, kEmpty);
        } else if (type == "sphere") {
            glm::vec3 c = g.vec3("center", {}, true);
            float r = static_cast<float>(g.number("radius", 8.0));
            if (r <= 0.0f || r > kMaxWorldExtent) fail(g.node("radius"), "'radius' must be in (0, {}]", kMaxWorldExtent);
            fillSphere(grid, c, r, material(g, scene, "material"));
        } else if (type == "cornell") {
            CornellParams p;
            p.origin = g.ivec3("origin", p.origin);
            p.interior = g.integer("interior", p.interior);
            p.wall = g.integer("wall", p.wall);
            p.lightBricks = g.integer("light_bricks", p.lightBricks);
            p.white = material(g, scene, "white");
            p.red = material(g, scene, "red");
            p.green = material(g, scene, "green");
            p.light = material(g, scene, "light");
            if (p.interior < 16 || p.interior % 8) fail(g.node("interior"), "'interior' must be a multiple of 8, >= 16");
            if (p.lightBricks * 8 > p.interior) fail(g.node("light_bricks"), "the light is wider than the box");
            generateCornellBox(grid, p);
        } else if (type == "buildings") {
            BuildingsParams p;
            p.count = g.integer("count", p.count);
            p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
            p.minHeight = g.integer("min_height", p.minHeight);
            p.maxHeight = g.integer("max_height", p.maxHeight);
            glm::ivec3 minSize = g.ivec3("min_size", {p.minSize.x, 0, p.minSize.y});
            glm::ivec3 maxSize = g.ivec3("max_size", {p.maxSize.x, 0, p.maxSize.y});
            p.minSize = {minSize.x, minSize.z};
            p.maxSize = {maxSize.x, maxSize.z};
            p.wall = material(g, scene, "wall");
            p.roof = material(g, scene, "roof");
            p.window = material(g, scene, "window");
            if (p.count < 0 || p.count > 10000) fail(g.node("count"), "'count' must be in 0..10000");
            if (glm::any(glm::lessThan(p.minSize, glm::ivec2(4))) || glm::any(glm::lessThan(p.maxSize, p.minSize)) ||
                p.minHeight < 6 || p.maxHeight < p.minHeight)
                fail(&node, "buildings: sizes must satisfy 4 <= min_size <= max_size and 6 <= min_height <= max_height");
            generateBuildings(grid, p);
        } else if (type == "lamps") {
            LampsParams p;
            p.count = g.integer("count", p.count);
            p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
            p.postHeight = g.integer("post_height", p.postHeight);
            p.lampSize = g.integer("lamp_size", p.lampSize);
            p.post = material(g, scene, "post");
            p.light = material(g, scene, "light");
            if (p.count < 0 || p.count > 1000000) fail(g.node("count"), "'count' must be in 0..1000000");
            if (p.lampSize < 1 || p.lampSize > 64) fail(g.node("lamp_size"), "'lamp_size' must be in 1..64");
            generateLamps(grid, p);
        } else if (type == "mountain") {
            parseMountain(g, scene);
        } else if (type == "scattered_lights") {
            parseScatteredLights(g, scene);
        } else if (type == "text") {
            parseText(g, scene);
        } else if (type == "menger") {
            parseMenger(g, scene);
        } else if (type == "apartment") {
            parseApartment(g, scene);
        } else if (type == "bridge") {
            parseBridge(g, scene);
        } else if (type == "vdb") {
            parseVdbGenerator(g, node, scene);
        } else if (type == "bricks") {
            // Saves by vox play before it wrote .vdb; the reader is gone (docs/SANDBOX.md says
            // how to convert one).
            fail(g.node("type"),
                 "generator 'bricks' (the .bricks payload of older vox play saves) is no longer supported; "
                 "saves are .vdb now (docs/SANDBOX.md, Saves)");
        } else {
            fail(g.node("type"), "unknown generator '{}' (known: {})", type, kGeneratorTypes);
        }
    }

    static constexpr const char* kGeneratorTypes =
        "terrain, box, sphere, cornell, buildings, lamps, mountain, scattered_lights, text, menger, apartment, bridge, "
        "vdb";

    void parseMountain(Table& g, Scene& scene) {
        MountainParams p;
        ColumnMaterials& m = p.materials;
        m.top = material(g, scene, "top");
        m.soil = material(g, scene, "soil");
        m.rock = material(g, scene, "rock");
        m.soilDepth = g.integer("soil_depth", m.soilDepth);
        m.snow = material(g, scene, "snow", "empty");
        m.snowLine = g.integer("snow_line", m.snowLine);
        m.cliff = material(g, scene, "cliff", "empty");
        m.cliffStep = g.integer("cliff_step", m.cliffStep);
        glm::vec3 size(scene.grid.sizeInVoxels());
        p.peak = g.vec2("peak", {size.x * 0.5f, size.z * 0.5f});
        p.peakHeight = static_cast<float>(g.number("peak_height", p.peakHeight));
        p.baseHeight = static_cast<float>(g.number("base_height", p.baseHeight));
        p.radius = static_cast<float>(g.number("radius", p.radius));
        p.hills = static_cast<float>(g.number("hills", p.hills));
        p.ridges = static_cast<float>(g.number("ridges", p.ridges));
        p.wavelength = static_cast<float>(g.number("wavelength", p.wavelength));
        p.octaves = g.integer("octaves", p.octaves);
        p.terrace = g.integer("terrace", p.terrace);
        p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
        if (p.octaves < 1 || p.octaves > 12) fail(g.node("octaves"), "'octaves' must be in 1..12");
        if (p.radius <= 0.0f) fail(g.node("radius"), "'radius' must be positive");
        if (p.ridges < 0.0f || p.ridges > 1.0f) fail(g.node("ridges"), "'ridges' must be in 0..1");
        if (p.terrace < 0 || p.terrace > 64) fail(g.node("terrace"), "'terrace' must be in 0..64");
        if (m.soilDepth < 0) fail(g.node("soil_depth"), "'soil_depth' must not be negative");
        generateMountain(scene.grid, p);
    }

    void parseScatteredLights(Table& g, Scene& scene) {
        ScatteredLightsParams p;
        p.spacing = g.integer("spacing", p.spacing);
        p.size = g.ivec3("size", p.size);
        p.margin = g.integer("margin", p.margin);
        p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
        p.light = material(g, scene, "light");
        if (p.spacing < 1 || p.spacing > 4096) fail(g.node("spacing"), "'spacing' must be in 1..4096");
        if (glm::any(glm::lessThan(p.size, glm::ivec3(1))) || p.size.x > p.spacing || p.size.z > p.spacing || p.size.y > 256)
            fail(g.node("size"), "'size' must be at least 1, at most 'spacing' across and 256 high");
        if (p.margin < 0) fail(g.node("margin"), "'margin' must not be negative");
        generateScatteredLights(scene.grid, p);
    }

    void parseText(Table& g, Scene& scene) {
        TextParams p;
        p.text = g.string("text");
        p.origin = g.ivec3("origin", {}, true);
        p.right = g.ivec3("right", p.right);
        p.up = g.ivec3("up", p.up);
        p.scale = g.integer("scale", p.scale);
        p.depth = g.integer("depth", p.depth);
        p.spacing = g.integer("spacing", p.spacing);
        p.material = material(g, scene, "material");
        if (std::string problem = validateTextParams(p); !problem.empty()) fail(&g.raw(), "text: {}", problem);
        generateText(scene.grid, p);
    }

    void parseMenger(Table& g, Scene& scene) {
        MengerParams p;
        p.origin = g.ivec3("origin", p.origin);
        p.level = g.integer("level", p.level);
        p.scale = g.integer("scale", p.scale);
        p.material = material(g, scene, "material");
        if (p.level < 0 || p.level > 6) fail(g.node("level"), "'level' must be in 0..6");
        if (p.scale < 1 || p.scale > 64) fail(g.node("scale"), "'scale' must be in 1..64");
        generateMenger(scene.grid, p);
    }

    void parseApartment(Table& g, Scene& scene) {
        ApartmentParams p;
        p.min = g.ivec3("min", {}, true);
        p.size = g.ivec3("size", {}, true);
        p.storey = g.integer("storey", p.storey);
        p.windowSize = g.ivec2("window_size", p.windowSize);
        p.windowSpacing = g.integer("window_spacing", p.windowSpacing);
        p.lit = static_cast<float>(g.number("lit", p.lit));
        p.balconies = static_cast<float>(g.number("balconies", p.balconies));
        p.baseDepth = g.integer("base_depth", p.baseDepth);
        p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
        p.wall = material(g, scene, "wall");
        p.slab = material(g, scene, "slab");
        p.railing = material(g, scene, "railing", "empty");
        p.base = material(g, scene, "base", "empty");
        p.cornerLight = material(g, scene, "corner_light", "empty");
        for (const std::string& name : g.strings("windows")) {
            auto id = scene.palette.find(name);
            if (!id) fail(g.node("windows"), "unknown material '{}'", name);
            p.windowLights.push_back(*id);
        }
        if (p.storey < 6 || p.storey > 64) fail(g.node("storey"), "'storey' must be in 6..64");
        if (p.size.x < 8 || p.size.z < 8 || p.size.y < p.storey + 1)
            fail(g.node("size"), "'size' must be at least 8 across and one storey ('storey' + 1) high");
        if (p.windowSize.x < 1 || p.windowSize.y < 1 || p.windowSpacing <= p.windowSize.x)
            fail(g.node("window_size"), "windows must be at least 1x1 and narrower than 'window_spacing'");
        if (p.lit < 0.0f || p.lit > 1.0f || p.balconies < 0.0f || p.balconies > 1.0f)
            fail(&g.raw(), "'lit' and 'balconies' are fractions in 0..1");
        if (p.baseDepth < 0) fail(g.node("base_depth"), "'base_depth' must not be negative");
        generateApartment(scene.grid, p);
    }

    void parseBridge(Table& g, Scene& scene) {
        BridgeParams p;
        p.min = g.ivec3("min", {}, true);
        p.max = g.ivec3("max", {}, true);
        p.railingHeight = g.integer("railing_height", p.railingHeight);
        p.postSpacing = g.integer("post_spacing", p.postSpacing);
        p.lightSpacing = g.integer("light_spacing", p.lightSpacing);
        p.deck = material(g, scene, "deck");
        p.railing = material(g, scene, "railing", "empty");
        p.light = material(g, scene, "light", "empty");
        if (Box{p.min, p.max}.empty()) fail(g.node("max"), "'max' must exceed 'min' on every axis");
        if (p.postSpacing < 1) fail(g.node("post_spacing"), "'post_spacing' must be positive");
        if (p.lightSpacing < 0) fail(g.node("light_spacing"), "'light_spacing' must not be negative");
        if (p.railingHeight < 0 || p.railingHeight > 64) fail(g.node("railing_height"), "'railing_height' must be in 0..64");
        generateBridge(scene.grid, p);
    }

    // An OpenVDB file (io/vdb_import.h); the keys mirror `vox import`'s options.
    void parseVdbGenerator(Table& g, const toml::node& node, Scene& scene) {
        namespace fs = std::filesystem;
        io::VdbImportOptions o;
        std::string source = g.string("source");
        fs::path path = fs::path(source).is_absolute() ? fs::path(source) : fs::path(mSource).parent_path() / source;
        o.grid = g.string("grid", "");
        o.colourGrid = g.string("colour_grid", "");
        std::string rule = g.string("rule", "auto");
        if (rule == "auto") o.rule = io::MaterialRule::Auto;
        else if (rule == "constant") o.rule = io::MaterialRule::Constant;
        else if (rule == "height") o.rule = io::MaterialRule::Height;
        else if (rule == "colour" || rule == "color") o.rule = io::MaterialRule::Colour;
        else if (rule == "ids") o.rule = io::MaterialRule::Ids;
        else fail(g.node("rule"), "unknown rule '{}' (known: auto, constant, height, colour, ids)", rule);
        if (g.has("material")) {
            MaterialId m = material(g, scene, "material");
            if (m == kEmpty) fail(g.node("material"), "'material' must be a solid material");
            o.material = scene.palette[m];
            if (o.rule == io::MaterialRule::Auto) o.rule = io::MaterialRule::Constant;
        }
        if (const toml::node* n = g.node("materials")) {
            const toml::array* a = n->as_array();
            if (!a || a->empty()) fail(n, "'materials' must be a non-empty array of material names");
            for (const toml::node& e : *a) {
                auto name = e.value<std::string>();
                auto id = name ? scene.palette.find(*name) : std::nullopt;
                if (!id) fail(n, "'materials': unknown material '{}'", name ? *name : "?");
                o.heightMaterials.push_back(scene.palette[*id]);
            }
        }
        o.fogThreshold = static_cast<float>(g.number("fog_threshold", o.fogThreshold));
        o.maxColours = g.integer("max_colours", o.maxColours);
        if (o.maxColours < 1 || std::size_t(o.maxColours) >= kMaxMaterials)
            fail(g.node("max_colours"), "'max_colours' must be in 1..{}", kMaxMaterials - 1);
        o.voxelSize = static_cast<float>(g.number("voxel_size", 0.0));
        if (o.voxelSize < 0.0f) fail(g.node("voxel_size"), "'voxel_size' must be positive");
        if (g.has("offset")) o.offset = g.ivec3("offset", {});
        if (g.has("crop_min") || g.has("crop_max")) {
            Box crop{g.ivec3("crop_min", {}, true), g.ivec3("crop_max", {}, true)};
            if (crop.empty()) fail(g.node("crop_max"), "'crop_max' must exceed 'crop_min' on every axis");
            o.crop = crop;
        }
        std::string up = g.string("up", "auto");
        if (up == "auto") o.up = io::UpAxis::Auto;
        else if (up == "y") o.up = io::UpAxis::Y;
        else if (up == "z") o.up = io::UpAxis::Z;
        else fail(g.node("up"), "'up' must be \"y\", \"z\" or \"auto\"");
        int budget = g.integer("memory_budget_mib", int(o.memoryBudgetBytes >> 20));
        if (budget < 1) fail(g.node("memory_budget_mib"), "'memory_budget_mib' must be positive");
        o.memoryBudgetBytes = std::uint64_t(budget) << 20;
        Status s = io::importVdbInto(scene, path, o);
        if (!s) fail(&node, "{}", s.error().message);
    }

    // A dynamic object (world/dynamic_object.h): its model is built by [[object.generator]]
    // tables, the same generators as the world's, run on the model's own grid in model
    // coordinates; [[object.key]] tables are its path.
    void parseObject(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[object]] must be a table");
        Table o(*this, *t);
        DynamicObject object;
        object.name = o.string("name", "object");
        object.modelSize = o.ivec3("size", {}, true);
        if (glm::any(glm::lessThan(object.modelSize, glm::ivec3(1))) ||
            glm::any(glm::greaterThan(object.modelSize, glm::ivec3(kMaxObjectExtent))))
            fail(o.node("size"), "object '{}': size must be 1..{} voxels per axis", object.name, kMaxObjectExtent);
        object.model = BrickGrid(object.modelSize);

        const toml::node* gens = o.node("generator");
        const toml::array* ga = gens ? gens->as_array() : nullptr;
        if (!ga || ga->empty())
            fail(gens ? gens : &node, "object '{}' needs at least one [[object.generator]] for its model", object.name);
        // The generators write scene.grid: lend them the model's grid for the while.
        std::swap(scene.grid, object.model);
        try {
            for (const toml::node& g : *ga) parseGenerator(g, scene);
        } catch (...) {
            std::swap(scene.grid, object.model);
            throw;
        }
        std::swap(scene.grid, object.model);
        object.model.clearDirty();
        if (object.model.solidVoxels() == 0) fail(gens, "object '{}': its generators leave the model empty", object.name);

        bool loop = o.boolean("loop", true);
        const toml::node* keys = o.node("key");
        const toml::array* ka = keys ? keys->as_array() : nullptr;
        if (!ka || ka->empty()) fail(keys ? keys : &node, "object '{}' needs at least one [[object.key]]", object.name);
        std::vector<ObjectKey> path;
        for (const toml::node& kn : *ka) {
            const toml::table* kt = kn.as_table();
            if (!kt) fail(&kn, "each [[object.key]] must be a table");
            Table k(*this, *kt);
            ObjectKey key;
            if (!k.has("time")) fail(&kn, "key: missing 'time'");
            key.time = k.number("time", 0.0);
            if (!path.empty() && !(key.time > path.back().time))
                fail(k.node("time"), "key times must increase ({} follows {})", key.time, path.back().time);
            key.position = glm::dvec3(k.vec3("position", {}, true));
            if (k.has("rotation") && (k.has("axis") || k.has("angle")))
                fail(&kn, "key: give 'rotation' or 'axis' and 'angle', not both");
            if (k.has("rotation")) {
                key.rotation = rotationFromYawPitchRoll(glm::dvec3(k.vec3("rotation", {})));
            } else if (k.has("axis") || k.has("angle")) {
                glm::dvec3 axis(k.vec3("axis", {0.0f, 1.0f, 0.0f}));
                if (glm::length(axis) < 1e-9) fail(k.node("axis"), "'axis' must not be zero");
                key.rotation = rotationFromAxisAngle(axis, k.number("angle", 0.0));
            }
            path.push_back(key);
        }
        if (loop && path.size() < 2) fail(keys, "a looping path needs at least two keys");
        object.path = ObjectPath(std::move(path), loop);
        scene.objects.push_back(std::move(object));
    }

    void parseCamera(const toml::node& node, Scene& scene) {
        const toml::table* t = node.as_table();
        if (!t) fail(&node, "each [[camera]] must be a table");
        Table c(*this, *t);
        CameraPreset cam;
        cam.name = c.string("name");
        cam.position = c.vec3("position", {}, true);
        cam.target = c.vec3("target", {}, true);
        cam.fovYDegrees = static_cast<float>(c.number("fov", 60.0));
        if (cam.fovYDegrees <= 1.0f || cam.fovYDegrees >= 179.0f) fail(c.node("fov"), "'fov' must be in (1, 179) degrees");
        if (glm::length(cam.target - cam.position) < 1e-4f) fail(&node, "camera '{}': target equals position", cam.name);
        scene.cameras.push_back(cam);
    }

    std::string mSource;
};

}  // namespace

Result<Scene> loadSceneText(std::string_view text, std::string_view sourceName) {
    try {
        toml::table root = toml::parse(text, sourceName);
        return SceneParser(std::string(sourceName)).parse(root);
    } catch (const toml::parse_error& e) {
        return makeError("{}:{}: {}", sourceName, e.source().begin.line, e.description());
    } catch (const ParseError& e) {
        return Error{e.message};
    }
}

Result<Scene> loadSceneFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError("{}: cannot open scene file", path.string());
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return makeError("{}: read error", path.string());
    return loadSceneText(text.str(), path.string());
}

std::string sceneFileText(const Scene& scene, std::string_view comment, std::string_view generators) {
    auto v3 = [](glm::vec3 v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); };
    auto quoted = [](const std::string& s) {
        std::string out = "\"";
        for (char c : s) {
            if (c == '"' || c == '\\') out += '\\';
            if (static_cast<unsigned char>(c) < 0x20) {
                out += fmt::format("\\u{:04x}", int(c));
                continue;
            }
            out += c;
        }
        return out + "\"";
    };
    std::string s;
    for (std::string_view line : {comment}) {
        std::size_t start = 0;
        while (start < line.size()) {
            std::size_t end = line.find('\n', start);
            if (end == std::string_view::npos) end = line.size();
            s += fmt::format("# {}\n", line.substr(start, end - start));
            start = end + 1;
        }
    }
    glm::ivec3 size = scene.grid.sizeInVoxels();
    s += fmt::format("[world]\nname = {}\nsize = [{}, {}, {}]\nvoxel_size = {}\n\n", quoted(scene.name), size.x, size.y,
                     size.z, scene.voxelSize);
    s += generators;
    for (const CameraPreset& c : scene.cameras)
        s += fmt::format("\n[[camera]]\nname = {}\nposition = {}\ntarget = {}\nfov = {}\n", quoted(c.name),
                         v3(c.position), v3(c.target), c.fovYDegrees);
    s += fmt::format("\n[sky]\nsun_direction = {}\nsun_radiance = {}\nsky_radiance = {}\n", v3(scene.sky.sunDirection),
                     v3(scene.sky.sunRadiance), v3(scene.sky.skyRadiance));
    return s;
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

}  // namespace engine::world
