// MagicaVoxel .vox import (io/vox_import.h): read the file, place its visible instances, check
// the world's size and memory before building it, then write the voxels.
#include "io/vox_import.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <new>

#include "core/allocation_budget.h"
#include "core/memory_budget.h"
#include "core/number_check.h"
#include "core/quoted_string.h"
#include "world/scene.h"
#include "world/world_limits.h"

namespace engine::io {

namespace fs = std::filesystem;

namespace {

// MagicaVoxel (x, y, z), Z-up, to engine axes before the shift: (x, z, -y).
glm::ivec3 toEngineAxes(glm::ivec3 v) { return {v.x, v.z, -v.y}; }

std::string mibText(std::uint64_t bytes) {
    return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20));
}

// The file read and placed: everything an import needs before it touches a world.
struct Placed {
    VoxFile file;
    std::vector<VoxInstance> instances;
    glm::ivec3 contentMin{0};  // engine axes, before the shift
    std::array<bool, 256> used{};
    VoxImportReport report;
};

Result<Placed> place(const fs::path& path, const VoxImportOptions& options,
                     const world::Scene* target) {
    auto file = readVoxFile(path);
    if (!file) return file.error();
    Placed p;
    p.file = std::move(*file);
    const std::string name = path.string();
    auto instances = voxInstances(p.file, name);
    if (!instances) return instances.error();
    p.instances = std::move(*instances);

    VoxImportReport& r = p.report;
    r.file = name;
    r.version = p.file.version;
    r.models = p.file.models.size();
    r.instances = p.instances.size();
    r.graphNodes = p.file.nodes.size();
    r.layers = p.file.layers.size();
    for (const auto& [id, layer] : p.file.layers) r.hiddenLayers += layer.hidden ? 1 : 0;
    r.defaultPalette = !p.file.hasPalette;
    r.budgetBytes = options.memoryBudgetBytes;

    // Each model's voxel bounds and colours once; each instance's bounds from two corners.
    struct ModelBounds {
        glm::ivec3 min{INT32_MAX}, max{INT32_MIN};
        std::array<bool, 256> colours{};
    };
    std::vector<ModelBounds> bounds(p.file.models.size());
    for (std::size_t m = 0; m < p.file.models.size(); ++m)
        for (const VoxVoxel& v : p.file.models[m].voxels) {
            bounds[m].min = glm::min(bounds[m].min, glm::ivec3(v.x, v.y, v.z));
            bounds[m].max = glm::max(bounds[m].max, glm::ivec3(v.x, v.y, v.z));
            bounds[m].colours[v.colour] = true;
        }
    glm::ivec3 lo(INT32_MAX), hi(INT32_MIN);
    for (const VoxInstance& in : p.instances) {
        const VoxModel& model = p.file.models[std::size_t(in.model)];
        const ModelBounds& b = bounds[std::size_t(in.model)];
        if (model.voxels.empty()) continue;
        r.placedVoxels += model.voxels.size();
        for (glm::ivec3 corner : {b.min, b.max}) {
            const glm::ivec3 e = toEngineAxes(voxPlace(in, model.size, corner));
            lo = glm::min(lo, e);
            hi = glm::max(hi, e);
        }
        for (int c = 1; c < 256; ++c)
            p.used[std::size_t(c)] = p.used[std::size_t(c)] || b.colours[std::size_t(c)];
    }
    if (r.placedVoxels > kVoxMaxPlacedVoxels)
        return makeError("{}: the scene graph places {} voxels, more than the {} an import writes",
                         name, r.placedVoxels, kVoxMaxPlacedVoxels);
    for (int c = 1; c < 256; ++c) {
        if (!p.used[std::size_t(c)]) continue;
        ++r.materials;
        auto m = p.file.materials.find(c);
        if (m != p.file.materials.end() && voxEmissionStrength(m->second) > 0.0f)
            ++r.emissiveMaterials;
    }
    if (r.placedVoxels == 0) {
        lo = hi = glm::ivec3(0);
        r.notes.push_back("no visible voxels: the world is empty");
    } else {
        r.contentSize = hi - lo + 1;
    }
    p.contentMin = lo;

    const glm::i64vec3 end =
        glm::i64vec3(options.offset) + glm::i64vec3(glm::max(r.contentSize, glm::ivec3(1)));
    if (target) {
        r.worldSize = target->grid.sizeInVoxels();
    } else {
        if (glm::any(glm::lessThan(options.offset, glm::ivec3(0))) ||
            glm::any(glm::greaterThan(end, glm::i64vec3(world::kMaxWorldExtent))))
            return makeError(
                "{}: the import would make a world of {}x{}x{} voxels (offset {}, {}, {}), over "
                "the "
                "engine's limit of {} per axis",
                name, end.x, end.y, end.z, options.offset.x, options.offset.y, options.offset.z,
                world::kMaxWorldExtent);
        r.worldSize = glm::ivec3(end);
    }
    const glm::u64vec3 cells =
        glm::u64vec3((glm::i64vec3(r.worldSize) + std::int64_t(7)) / std::int64_t(8));
    const std::uint64_t cellCount = cells.x * cells.y * cells.z;
    if (!target && cellCount > world::kMaxTopGridCells)
        return makeError(
            "{}: the import would make a world of {}x{}x{} voxels, over the engine's limit of {} "
            "top-grid "
            "cells",
            name, r.worldSize.x, r.worldSize.y, r.worldSize.z, world::kMaxTopGridCells);
    // Top grid, super grid and dirty flags, plus at most one brick per placed voxel.
    const std::uint64_t bricks = std::min(r.placedVoxels, cellCount);
    std::uint64_t largestModel = 0;  // the dense box one instance is placed through
    for (const VoxModel& m : p.file.models)
        largestModel = std::max(largestModel, std::uint64_t(m.size.x) * std::uint64_t(m.size.y) *
                                                  std::uint64_t(m.size.z));
    std::error_code ec;
    const std::uint64_t fileBytes =
        fs::file_size(path, ec);  // read whole while the chunks are parsed
    r.estimateBytes = (target ? 0 : cellCount * 6) + world::BrickGrid::poolBytesFor(bricks) +
                      p.file.models.size() * 64 + largestModel * sizeof(world::MaterialId) +
                      (ec ? 0 : fileBytes);
    for (const VoxModel& m : p.file.models) r.estimateBytes += m.voxels.size() * sizeof(VoxVoxel);
    if (r.estimateBytes > options.memoryBudgetBytes)
        return makeError(
            "{}: importing it would need about {} (world {}x{}x{}), over the memory budget of {} "
            "({})",
            name, mibText(r.estimateBytes), r.worldSize.x, r.worldSize.y, r.worldSize.z,
            mibText(options.memoryBudgetBytes), memoryBudgetAdvice(options.memoryBudgetBytes));
    if (!p.file.skippedChunks.empty()) {
        std::string skipped;
        for (const auto& [id, count] : p.file.skippedChunks)
            skipped += fmt::format("{}{} x{}", skipped.empty() ? "" : ", ", id, count);
        r.notes.push_back("chunks not used: " + skipped);
    }
    return p;
}

Status build(Placed& p, world::Scene& scene, bool intoExisting, const VoxImportOptions& options) {
    // Names are printable text wherever they come from (a scene file refuses others).
    const std::string stem = printableText(fs::path(p.report.file).stem().string());
    std::array<world::MaterialId, 256> ids{};
    for (int c = 1; c < 256; ++c) {
        if (!p.used[std::size_t(c)]) continue;
        world::Material m;
        m.name = fmt::format("{}_{}", stem, c);
        m.albedo = voxColourToLinear(p.file.palette[std::size_t(c)]);
        if (auto matl = p.file.materials.find(c); matl != p.file.materials.end()) {
            m.emissionStrength = voxEmissionStrength(matl->second);
            // The scene key's check (world/scene.h): a file cannot make a world no scene file
            // holds.
            if (Status ok = checkNumber(fmt::format("material {} emission (_emit x 2^_flux)", c),
                                        m.emissionStrength, world::kRadianceRange);
                !ok)
                return makeError("{}: {}", p.report.file, ok.error().message);
            if (m.emissionStrength > 0.0f) m.emissionColor = m.albedo;
        }
        std::optional<world::MaterialId> id;
        if (intoExisting) id = scene.palette.find(m.name);
        if (!id) id = scene.palette.add(m);
        if (!id)
            return makeError("{}: the palette is full ({} materials)", p.report.file,
                             world::kMaxMaterials - 1);
        ids[std::size_t(c)] = *id;
    }
    world::BrickGrid& grid = scene.grid;
    if (!intoExisting) grid = world::BrickGrid(p.report.worldSize);
    const glm::ivec3 shift = options.offset - p.contentMin;
    // One instance at a time: its voxels into a dense box (at most 256^3), then that box into the
    // grid a whole cell at a time — a voxel-by-voxel set() keeps the grid's counts and skip
    // distances up to date on every call and is ~20x slower on large files.
    std::vector<world::MaterialId> dense;
    for (const VoxInstance& in : p.instances) {
        const VoxModel& model = p.file.models[std::size_t(in.model)];
        if (model.voxels.empty()) continue;
        const glm::ivec3 a = toEngineAxes(voxPlace(in, model.size, glm::ivec3(0))) + shift;
        const glm::ivec3 b = toEngineAxes(voxPlace(in, model.size, model.size - 1)) + shift;
        const world::Box box =
            world::Box{glm::min(a, b), glm::max(a, b) + 1}.intersect(grid.bounds());
        if (box.empty()) continue;
        const glm::ivec3 n = box.size();
        auto at = [&](glm::ivec3 q) {
            return std::size_t(q.x) +
                   std::size_t(n.x) * (std::size_t(q.y) + std::size_t(n.y) * std::size_t(q.z));
        };
        dense.assign(std::size_t(n.x) * std::size_t(n.y) * std::size_t(n.z), world::kEmpty);
        for (const VoxVoxel& v : model.voxels) {
            const glm::ivec3 e =
                toEngineAxes(voxPlace(in, model.size, glm::ivec3(v.x, v.y, v.z))) + shift;
            if (box.contains(e)) dense[at(e - box.min)] = ids[v.colour];
        }
        const glm::ivec3 c0 = box.min / world::kBrickDim, c1 = (box.max - 1) / world::kBrickDim;
        for (int cz = c0.z; cz <= c1.z; ++cz)
            for (int cy = c0.y; cy <= c1.y; ++cy)
                for (int cx = c0.x; cx <= c1.x; ++cx) {
                    const glm::ivec3 c(cx, cy, cz);
                    world::BrickVoxels voxels = grid.readCell(c);
                    bool changed = false;
                    for (int i = 0; i < world::kBrickVoxels; ++i) {
                        const glm::ivec3 q = c * world::kBrickDim + world::brickVoxelPosition(i);
                        if (!box.contains(q)) continue;
                        if (world::MaterialId m = dense[at(q - box.min)])
                            voxels[std::size_t(i)] = m, changed = true;
                    }
                    if (changed) grid.writeCell(c, voxels);
                }
    }
    grid.clearDirty();
    p.report.solidVoxels = grid.solidVoxels();
    if (!intoExisting) {
        scene.name = stem;
        scene.voxelSize = 1.0f;
        scene.sourcePath = p.report.file;
    }
    return {};
}

// Runs an import step under the memory budget: a refused allocation becomes an error naming the
// file.
template <typename T, typename F>
Result<T> guarded(const fs::path& path, const VoxImportOptions& options, F&& f) {
    AllocationBudget budget(options.memoryBudgetBytes, options.memoryBudgetBytes);
    try {
        return f(budget);
    } catch (const std::bad_alloc&) {
        return makeError("{}: importing it needs more memory than the budget of {} allows ({})",
                         path.string(), mibText(options.memoryBudgetBytes),
                         memoryBudgetAdvice(options.memoryBudgetBytes));
    }
}

}  // namespace

glm::vec3 voxColourToLinear(std::uint32_t rgba) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        const float c = float((rgba >> (8 * i)) & 0xFF) / 255.0f;
        out[i] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return out;
}

std::uint32_t voxColourFromLinear(glm::vec3 linear) {
    std::uint32_t out = 0xFF000000u;
    for (int i = 0; i < 3; ++i) {
        const float c = std::clamp(std::isnan(linear[i]) ? 0.0f : linear[i], 0.0f, 1.0f);
        const float s = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
        out |= std::uint32_t(std::lround(std::clamp(s, 0.0f, 1.0f) * 255.0f)) << (8 * i);
    }
    return out;
}

float voxEmissionStrength(const VoxMaterial& m) {
    if (m.type != "_emit" || !(m.emit > 0.0f)) return 0.0f;
    return kVoxEmissionScale * m.emit * std::exp2(std::clamp(m.flux, 0.0f, 8.0f));
}

void voxEmitFlux(float strength, float& emit, float& flux) {
    // The lowest whole power of two that keeps _emit within MagicaVoxel's 0..1 (up to _flux 4);
    // a power of two divides exactly, so voxEmissionStrength gives `strength` back.
    flux = 0.0f;
    while (flux < 4.0f && strength > kVoxEmissionScale * std::exp2(flux)) flux += 1.0f;
    emit = strength / (kVoxEmissionScale * std::exp2(flux));
}

Result<VoxImportReport> planVoxImport(const fs::path& path, const VoxImportOptions& options) {
    return guarded<VoxImportReport>(path, options,
                                    [&](const AllocationBudget&) -> Result<VoxImportReport> {
                                        auto p = place(path, options, nullptr);
                                        if (!p) return p.error();
                                        return p->report;
                                    });
}

Result<world::Scene> importVox(const fs::path& path, const VoxImportOptions& options,
                               VoxImportReport* report) {
    return guarded<world::Scene>(path, options,
                                 [&](const AllocationBudget& budget) -> Result<world::Scene> {
                                     auto p = place(path, options, nullptr);
                                     if (!p) return p.error();
                                     world::Scene scene;
                                     if (Status s = build(*p, scene, false, options); !s)
                                         return s.error();
                                     p->report.peakTrackedBytes = budget.peakBytes();
                                     if (report) *report = p->report;
                                     return scene;
                                 });
}

Status importVoxInto(world::Scene& scene, const fs::path& path, const VoxImportOptions& options,
                     VoxImportReport* report) {
    auto done = guarded<bool>(path, options, [&](const AllocationBudget& budget) -> Result<bool> {
        auto p = place(path, options, &scene);
        if (!p) return p.error();
        if (Status s = build(*p, scene, true, options); !s) return s.error();
        p->report.peakTrackedBytes = budget.peakBytes();
        if (report) *report = p->report;
        return true;
    });
    if (!done) return done.error();
    return {};
}

std::string formatVoxImportReport(const VoxImportReport& r, bool planned) {
    std::string s;
    s += fmt::format("  format       MagicaVoxel .vox, version {}\n", r.version);
    s += fmt::format(
        "  models       {} model(s), {} visible instance(s); scene graph of {} node(s), {} "
        "layer(s) ({} "
        "hidden)\n",
        r.models, r.instances, r.graphNodes, r.layers, r.hiddenLayers);
    s +=
        fmt::format("  materials    {} colour(s) in use ({} palette), {} emissive\n", r.materials,
                    r.defaultPalette ? "MagicaVoxel's default" : "the file's", r.emissiveMaterials);
    s += "  axes         Z-up turned to Y-up: MagicaVoxel (x, y, z) -> (x, z, -y)\n";
    s += fmt::format("  world        {} x {} x {} voxels; content {} x {} x {}\n", r.worldSize.x,
                     r.worldSize.y, r.worldSize.z, r.contentSize.x, r.contentSize.y,
                     r.contentSize.z);
    s += fmt::format("  memory       about {}; budget {}\n", mibText(r.estimateBytes),
                     mibText(r.budgetBytes));
    if (planned)
        s += fmt::format("  voxels       {} placed by the scene graph\n", r.placedVoxels);
    else
        s += fmt::format(
            "  imported     {} solid voxels ({} placed; overlaps keep the later instance)\n",
            r.solidVoxels, r.placedVoxels);
    for (const std::string& n : r.notes) s += fmt::format("  note         {}\n", n);
    return s;
}

}  // namespace engine::io
