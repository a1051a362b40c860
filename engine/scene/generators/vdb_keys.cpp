// [[generator]] type = "vdb": an OpenVDB file through io/vdb_import.h; the keys mirror
// `vox import`'s options. Written back with only the keys that differ from the defaults, so a
// save names its payload and rule and nothing it did not choose.
#include "scene/generators/vdb_keys.h"

#include <cmath>
#include <filesystem>

#include "core/log.h"
#include "io/vdb_import.h"
#include "scene/generator_registry.h"

namespace engine::scene {

namespace {

struct VdbParams {
    std::string source;  // as written: relative to the scene file's folder, or absolute
    io::VdbImportOptions options;
    bool hasMaterial = false;  // `material` given (the constant rule's material)
};

constexpr std::pair<io::MaterialRule, const char*> kRules[] = {
    {io::MaterialRule::Auto, "auto"},
    {io::MaterialRule::Constant, "constant"},
    {io::MaterialRule::Height, "height"},
    {io::MaterialRule::Colour, "colour"},
    {io::MaterialRule::Ids, "ids"}};
constexpr std::pair<io::UpAxis, const char*> kUps[] = {
    {io::UpAxis::Auto, "auto"}, {io::UpAxis::Y, "y"}, {io::UpAxis::Z, "z"}};

VdbParams parse(GeneratorKeys& g) {
    VdbParams p;
    io::VdbImportOptions& o = p.options;
    p.source = g.string("source");
    o.grid = g.string("grid", "");
    o.colourGrid = g.string("colour_grid", "");
    std::string rule = g.string("rule", "auto");
    if (rule == "color") rule = "colour";
    bool known = false;
    for (auto [r, name] : kRules) {
        if (rule == name) o.rule = r, known = true;
    }
    if (!known)
        g.fail(g.node("rule"), "unknown rule '{}' (known: auto, constant, height, colour, ids)",
               rule);
    if (g.has("material")) {
        world::MaterialId m = g.material("material");
        if (m == world::kEmpty) g.fail(g.node("material"), "'material' must be a solid material");
        o.material = g.scene().palette[m];
        p.hasMaterial = true;
        if (o.rule == io::MaterialRule::Auto) o.rule = io::MaterialRule::Constant;
    }
    if (const toml::node* n = g.node("materials")) {
        const toml::array* a = n->as_array();
        if (!a || a->empty()) g.fail(n, "'materials' must be a non-empty array of material names");
        for (const toml::node& e : *a) {
            auto name = e.value<std::string>();
            auto id = name ? g.scene().palette.find(*name) : std::nullopt;
            if (!id) g.fail(n, "'materials': unknown material '{}'", name ? *name : "?");
            o.heightMaterials.push_back(g.scene().palette[*id]);
        }
    }
    o.fogThreshold =
        static_cast<float>(g.number("fog_threshold", o.fogThreshold, closedRange(-1e6, 1e6)));
    o.maxColours =
        g.integer("max_colours", o.maxColours, wholeRange(1, double(world::kMaxMaterials - 1)));
    // Absent: the file's own voxel size (0 in the options); 0 in the file is refused.
    o.voxelSize = g.number("voxel_size", 0.0, aboveRange(0.0, 1e6, "file units"));
    if (g.has("offset")) o.offset = g.ivec3("offset", {}, kVoxelIndexRange);
    if (g.has("crop_min") || g.has("crop_max")) {
        world::Box crop{g.ivec3("crop_min", {}, kVoxelIndexRange, true),
                        g.ivec3("crop_max", {}, kVoxelIndexRange, true)};
        if (crop.empty())
            g.fail(g.node("crop_max"), "'crop_max' must exceed 'crop_min' on every axis");
        o.crop = crop;
    }
    std::string up = g.string("up", "auto");
    known = false;
    for (auto [axis, name] : kUps) {
        if (up == name) o.up = axis, known = true;
    }
    if (!known) g.fail(g.node("up"), "'up' must be \"y\", \"z\" or \"auto\"");
    int budget = g.integer("memory_budget_mib", int(o.memoryBudgetBytes >> 20),
                           wholeRange(1, 1 << 24, "MiB"));
    o.memoryBudgetBytes = std::uint64_t(budget) << 20;
    return p;
}

Status run(const VdbParams& p, world::Scene& scene) {
    namespace fs = std::filesystem;
    fs::path path = fs::path(p.source).is_absolute()
                        ? fs::path(p.source)
                        : fs::path(scene.sourcePath).parent_path() / p.source;
    io::VdbImportReport report;
    if (Status s = io::importVdbInto(scene, path, p.options, &report); !s) return s;
    // The notes `vox import` prints (content cut off at the world's edge, axes turned, resampling).
    for (const std::string& note : report.plan.notes)
        log::warn("{}: vdb generator, {}: {}", scene.sourcePath, p.source, note);
    return {};
}

void write(const VdbParams& p, const GeneratorWriter& out) {
    const io::VdbImportOptions& o = p.options;
    const io::VdbImportOptions defaults;
    TomlWriter& t = out.toml;
    t.key("source", p.source);
    if (!o.grid.empty()) t.key("grid", o.grid);
    if (!o.colourGrid.empty()) t.key("colour_grid", o.colourGrid);
    for (auto [r, name] : kRules) {
        if (o.rule == r && r != io::MaterialRule::Auto) t.key("rule", name);
    }
    if (p.hasMaterial) t.key("material", o.material.name);
    if (!o.heightMaterials.empty()) {
        std::vector<std::string> names;
        for (const world::Material& m : o.heightMaterials) names.push_back(m.name);
        t.key("materials", names);
    }
    if (o.fogThreshold != defaults.fogThreshold) t.key("fog_threshold", o.fogThreshold);
    if (o.maxColours != defaults.maxColours) t.key("max_colours", o.maxColours);
    if (o.voxelSize != 0.0) t.key("voxel_size", o.voxelSize);
    if (o.offset) t.key("offset", *o.offset);
    if (o.crop) {
        t.key("crop_min", o.crop->min);
        t.key("crop_max", o.crop->max);
    }
    for (auto [axis, name] : kUps) {
        if (o.up == axis && axis != io::UpAxis::Auto) t.key("up", name);
    }
    if (o.memoryBudgetBytes != defaults.memoryBudgetBytes)
        t.key("memory_budget_mib", int(o.memoryBudgetBytes >> 20));
}

}  // namespace

extern const GeneratorEntry kVdbGenerator = makeGeneratorEntry<VdbParams, parse, run, write>("vdb");

// A `vdb` generator record for a payload written beside a scene file (saves, `vox import`).
world::GeneratorRecord vdbPayloadGenerator(std::string source, bool ids) {
    VdbParams p;
    p.source = std::move(source);
    if (ids) p.options.rule = io::MaterialRule::Ids;
    return {"vdb", p};
}

}  // namespace engine::scene
