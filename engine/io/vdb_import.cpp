// OpenVDB import's entry points (io/vdb_import.h): run the steps of io/vdb_import_state.h under
// an allocation budget, turn what OpenVDB throws into an Error naming the file, and describe
// plans and reports in words.
#include "io/vdb_import.h"

#include <algorithm>
#include <fmt/format.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/allocation_budget.h"
#include "core/quoted_string.h"
#include "io/vdb_import_state.h"

namespace engine::io {

namespace fs = std::filesystem;
using namespace vdb_import;

namespace {

// Builds the planned import into `scene`: a new world, or into an existing one.
Status buildWorld(ImportState& im, world::Scene& scene, bool intoExisting) {
#if defined(__GLIBC__)
    // Planning freed the source topology (thousands of small nodes); hand those pages back to
    // the system before the world is built, or they stay resident as heap fragments. And pin
    // glibc's mmap threshold: OpenVDB's node buffers (128-768 KiB, allocated and freed per node)
    // otherwise raise it, after which they are carved from the heap and linger there.
    malloc_trim(0);
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
    if (Status s = buildPalette(im); !s) return s;
    if (Status s = addToScenePalette(im, scene, intoExisting); !s) return s;

    const Placement& place = im.place;
    world::BrickGrid& grid = scene.grid;
    std::vector<std::uint8_t> marks;
    {
        AllocationBudget::LargeAllocations large;  // checked by the estimate
        if (!intoExisting) grid = world::BrickGrid(place.worldSize);
        const std::uint64_t bricks = grid.liveBricks() + im.plan.sampledCells;
        grid.reserveBricks(std::uint32_t(std::min<std::uint64_t>(bricks, 0x7FFFFFF0u)));
        if (!im.streaming)
            marks.assign(std::size_t(volume(Box{glm::ivec3(0), (place.worldSize + 7) / 8})),
                         kCellNone);
    }
    if (im.streaming) {
        if (Status s = streamIntoWorld(im, grid); !s) return s;
        grid.clearDirty();
        im.slabs.clear();
    } else {
        // Cells that solid tiles fill whole are written here; the slabs read the rest.
        auto topology = makeSource(*im.grids.shapeHeader);
        topology->attach(im.reader.readTopology(im.grids.shapeIndex));
        DirtyListBound dirty(grid);
        Status marked = markCells(im, *topology, marks, [&](glm::ivec3 c, int material) {
            grid.writeCellUniform(c, im.palette.remap[std::size_t(material)]);
            im.report.solidVoxels += world::kBrickVoxels;
            dirty.noteWrite();
        });
        if (!marked) return marked;
    }
    grid.clearDirty();
    if (Status s = fillSlabs(im, grid, marks, intoExisting); !s) return s;
    if (im.grids.kind == Kind::Fog && im.report.solidVoxels == 0) {
        // A fog threshold above the data: say so rather than write an empty world.
        if (im.largestFogValue >= double(im.options.fogThreshold))
            return makeError(
                "{}: no voxel of grid '{}' at or above the fog threshold {:g} lands inside the "
                "world",
                im.file, im.plan.grid, im.options.fogThreshold);
        const bool everyVoxel = im.place.map.scale == glm::dvec3(1.0);
        return makeError(
            "{}: no voxel of grid '{}' reaches the fog threshold {:g}: the largest density {} is "
            "{:g} "
            "(lower --fog-threshold, fog_threshold in a scene file)",
            im.file, im.plan.grid, im.options.fogThreshold, everyVoxel ? "in it" : "sampled",
            im.largestFogValue);
    }

    const ColourError& colourError = im.palette.colourError;
    im.report.colouredVoxels = colourError.count;
    im.report.meanColourError = colourError.mean();
    im.report.maxColourError = colourError.max;

    if (!intoExisting) {
        const ChosenGrids& g = im.grids;
        // Names are printable text wherever they come from (a scene file refuses others).
        scene.name = g.voxengine ? g.worldHeader.name : printableText(im.path.stem().string());
        scene.voxelSize = float(im.plan.voxelSize);
        if (g.voxengine) {
            scene.cameras = g.worldHeader.cameras;
            scene.sky = g.worldHeader.sky;
        }
        // Into an existing scene the scene file stays the source: `vox capture` reads its [path]
        // from there, and messages name it.
        scene.sourcePath = im.file;
    }
    return {};
}

// The boundary: OpenVDB, the reader and the allocation budget throw (a damaged file, memory
// refused); everything the import does runs inside this one catch, which names the file.
template <typename T>
Result<T> runGuarded(const fs::path& path, const VdbImportOptions& options,
                     const std::function<Result<T>(const AllocationBudget&)>& f) {
    auto bytes = vdbFileBytes(path);
    if (!bytes) return bytes.error();
    AllocationBudget budget(options.memoryBudgetBytes, vdbSingleAllocationLimit(*bytes));
    try {
        return f(budget);
    } catch (...) {
        return vdbError(path, &budget);
    }
}

void finishReport(ImportState& im, const AllocationBudget& budget, VdbImportReport* report) {
    im.report.peakTrackedBytes = budget.peakBytes();
    if (report) *report = im.report;
}

}  // namespace

Result<VdbImportPlan> planVdbImport(const fs::path& path, const VdbImportOptions& options) {
    return runGuarded<VdbImportPlan>(path, options,
                                     [&](const AllocationBudget&) -> Result<VdbImportPlan> {
                                         ImportState im(path, options);
                                         if (Status s = planImport(im, nullptr); !s)
                                             return s.error();
                                         return im.report.plan;
                                     });
}

Result<world::Scene> importVdb(const fs::path& path, const VdbImportOptions& options,
                               VdbImportReport* report) {
    return runGuarded<world::Scene>(
        path, options, [&](const AllocationBudget& budget) -> Result<world::Scene> {
            ImportState im(path, options);
            if (Status s = planImport(im, nullptr); !s) return s.error();
            world::Scene scene;
            if (Status s = buildWorld(im, scene, /*intoExisting=*/false); !s) return s.error();
            finishReport(im, budget, report);
            return scene;
        });
}

Status importVdbInto(world::Scene& scene, const fs::path& path, const VdbImportOptions& options,
                     VdbImportReport* report) {
    auto done =
        runGuarded<bool>(path, options, [&](const AllocationBudget& budget) -> Result<bool> {
            ImportState im(path, options);
            if (Status s = planImport(im, &scene); !s) return s.error();
            if (Status s = buildWorld(im, scene, /*intoExisting=*/true); !s) return s.error();
            finishReport(im, budget, report);
            return true;
        });
    if (!done) return done.error();
    return {};
}

std::string formatVdbImportPlan(const VdbImportPlan& p) {
    std::string s;
    s += fmt::format("  grid         '{}' ({}, class {}) as {}\n", p.grid, p.gridType, p.gridClass,
                     p.kind);
    s += fmt::format("  materials    {}\n", p.rule);
    s += fmt::format("  axes         {}; voxel size {:.6g} (source {:.6g} x {:.6g} x {:.6g})\n",
                     p.upZ ? "Z-up turned to Y-up" : "Y-up, as stored", p.voxelSize,
                     p.sourceVoxelSize.x, p.sourceVoxelSize.y, p.sourceVoxelSize.z);
    s += fmt::format("  source box   [{}, {}, {}] .. [{}, {}, {}] (index space, max exclusive)\n",
                     p.sourceBox.min.x, p.sourceBox.min.y, p.sourceBox.min.z, p.sourceBox.max.x,
                     p.sourceBox.max.y, p.sourceBox.max.z);
    s +=
        fmt::format("  world        {} x {} x {} voxels; content at [{}, {}, {}] .. [{}, {}, {}]\n",
                    p.worldSize.x, p.worldSize.y, p.worldSize.z, p.worldBox.min.x, p.worldBox.min.y,
                    p.worldBox.min.z, p.worldBox.max.x, p.worldBox.max.y, p.worldBox.max.z);
    s += fmt::format(
        "  cells        {} read voxel by voxel (at most that many bricks), {} filled whole from "
        "tiles\n",
        p.sampledCells, p.uniformCells);
    s += fmt::format("  memory       about {} ({} world, {} source {}); budget {}\n",
                     mib(p.estimateBytes), mib(p.worldBytes), mib(p.sourceBytes),
                     p.streamed ? std::string("streamed leaf by leaf")
                                : fmt::format("read in {} slab(s)", p.slabs),
                     mib(p.budgetBytes));
    for (const std::string& n : p.notes) s += fmt::format("  note         {}\n", n);
    return s;
}

std::string formatVdbImportReport(const VdbImportReport& r) {
    std::string s = formatVdbImportPlan(r.plan);
    s +=
        fmt::format("  imported     {} solid voxels, {} material(s)\n", r.solidVoxels, r.materials);
    if (r.colours > 0)
        s += fmt::format(
            "  colour error {} voxels mapped to {} colours: mean {:.4f}, max {:.4f} (linear RGB "
            "distance)\n",
            r.colouredVoxels, r.colours, r.meanColourError, r.maxColourError);
    return s;
}

}  // namespace engine::io
