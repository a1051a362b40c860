#include "io/vdb_import.h"

#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <cctype>
#include <fstream>
#include <cmath>
#include <functional>
#include <memory>
#include <unordered_map>

#include <fmt/format.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/allocation_budget.h"
#include "io/colour_quantizer.h"
#include "io/vdb_layout.h"
#include "io/vdb_reader.h"
#include "io/vdb_tree_stream.h"
#include "world/world_limits.h"

namespace engine::io {

namespace fs = std::filesystem;
namespace vdb = openvdb;
using world::BrickGrid;
using world::Box;
using world::MaterialId;

namespace {

// Thrown inside the import (where OpenVDB may throw anyway) and turned into an Error at the
// boundary; the message already names the file.
struct ImportFailure {
    std::string message;
};
template <typename... Args>
[[noreturn]] void failImport(fmt::format_string<Args...> f, Args&&... args) {
    throw ImportFailure{fmt::format(f, std::forward<Args>(args)...)};
}

std::string mib(std::uint64_t bytes) { return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20)); }

enum class Kind { VoxIds, LevelSet, Fog, Ids, Mask, Colour };

const char* kindName(Kind k) {
    switch (k) {
        case Kind::VoxIds: return "voxengine world";
        case Kind::LevelSet: return "level set";
        case Kind::Fog: return "fog volume";
        case Kind::Ids: return "integer ids";
        case Kind::Mask: return "mask";
        case Kind::Colour: return "colour";
    }
    return "?";
}

// ---------------------------------------------------------------------------------------------
// A type-erased view of one grid: just the parts of OpenVDB the importer needs, so the import
// logic below is written once instead of once per value type.

struct Sample {
    double scalar = 0.0;
    glm::vec3 colour{0.0f};
    bool active = false;
};

template <typename T>
Sample toSample(const T& v, bool on) {
    Sample s;
    s.active = on;
    if constexpr (std::is_same_v<T, bool>) {
        s.scalar = v ? 1.0 : 0.0;
    } else if constexpr (std::is_arithmetic_v<T>) {
        s.scalar = double(v);
    } else {
        s.colour = glm::vec3(float(v.x()), float(v.y()), float(v.z()));
    }
    return s;
}

class SourceGrid {
public:
    virtual ~SourceGrid() = default;
    virtual void attach(vdb::GridBase::Ptr grid) = 0;  // as read by VdbReader; nullptr releases it
    virtual vdb::GridBase::ConstPtr base() const = 0;
    virtual Sample at(const vdb::Coord& ijk) const = 0;     // leaf values must be loaded
    virtual double trilinear(const vdb::Vec3d& ijk) const = 0;  // index space, voxel centres at integers
    // Leaves (node box, active voxel count) and tiles above leaf level (box, value).
    virtual void forEachLeaf(const std::function<void(const vdb::CoordBBox&, std::uint64_t)>& f) const = 0;
    virtual void forEachTile(const std::function<void(const vdb::CoordBBox&, const Sample&)>& f) const = 0;
    // Active voxels inside `box` of the loaded leaves whose origin lies in `origins`.
    virtual void forEachActiveLeafVoxel(const vdb::CoordBBox& origins, const vdb::CoordBBox& box,
                                        const std::function<void(const Sample&)>& f) const = 0;
};

template <typename GridT>
class TypedSource final : public SourceGrid {
public:
    using ValueT = typename GridT::ValueType;

    void attach(vdb::GridBase::Ptr grid) override {
        mAccessor.reset();
        mGrid.reset();
        if (!grid) return;
        mGrid = vdb::GridBase::grid<GridT>(grid);
        if (!mGrid) throw vdb::TypeError("grid changed type between reads");
        mAccessor = std::make_unique<typename GridT::ConstAccessor>(mGrid->getConstAccessor());
    }
    vdb::GridBase::ConstPtr base() const override { return mGrid; }
    Sample at(const vdb::Coord& ijk) const override {
        ValueT v;
        bool on = mAccessor->probeValue(ijk, v);
        return toSample(v, on);
    }
    double trilinear(const vdb::Vec3d& ijk) const override {
        if constexpr (std::is_floating_point_v<ValueT>) {
            return double(vdb::tools::BoxSampler::sample(*mAccessor, ijk));
        } else {
            return at(vdb::Coord::round(ijk)).scalar;
        }
    }
    void forEachLeaf(const std::function<void(const vdb::CoordBBox&, std::uint64_t)>& f) const override {
        for (auto it = mGrid->tree().cbeginLeaf(); it; ++it) f(it->getNodeBoundingBox(), it->onVoxelCount());
    }
    void forEachTile(const std::function<void(const vdb::CoordBBox&, const Sample&)>& f) const override {
        auto it = mGrid->tree().cbeginValueAll();
        it.setMaxDepth(it.getLeafDepth() - 1);  // tiles only: never look at leaf values
        for (; it; ++it) {
            vdb::CoordBBox box;
            it.getBoundingBox(box);
            f(box, toSample(*it, it.isValueOn()));
        }
    }
    void forEachActiveLeafVoxel(const vdb::CoordBBox& origins, const vdb::CoordBBox& box,
                                const std::function<void(const Sample&)>& f) const override {
        for (auto leaf = mGrid->tree().cbeginLeaf(); leaf; ++leaf) {
            if (!origins.isInside(leaf->origin())) continue;
            for (auto v = leaf->cbeginValueOn(); v; ++v)
                if (box.isInside(v.getCoord())) f(toSample(*v, true));
        }
    }

private:
    typename GridT::Ptr mGrid;
    std::unique_ptr<typename GridT::ConstAccessor> mAccessor;
};

std::unique_ptr<SourceGrid> makeSource(const vdb::GridBase& g) {
    if (g.isType<vdb::FloatGrid>()) return std::make_unique<TypedSource<vdb::FloatGrid>>();
    if (g.isType<vdb::DoubleGrid>()) return std::make_unique<TypedSource<vdb::DoubleGrid>>();
    if (g.isType<vdb::Int32Grid>()) return std::make_unique<TypedSource<vdb::Int32Grid>>();
    if (g.isType<vdb::Int64Grid>()) return std::make_unique<TypedSource<vdb::Int64Grid>>();
    if (g.isType<vdb::BoolGrid>()) return std::make_unique<TypedSource<vdb::BoolGrid>>();
    if (g.isType<vdb::MaskGrid>()) return std::make_unique<TypedSource<vdb::MaskGrid>>();
    if (g.isType<vdb::Vec3SGrid>()) return std::make_unique<TypedSource<vdb::Vec3SGrid>>();
    if (g.isType<vdb::Vec3DGrid>()) return std::make_unique<TypedSource<vdb::Vec3DGrid>>();
    return nullptr;
}

bool isColourType(const vdb::GridBase& g) { return g.isType<vdb::Vec3SGrid>() || g.isType<vdb::Vec3DGrid>(); }

std::optional<Kind> kindOf(const vdb::GridBase& g) {
    if (g.isType<vdb::FloatGrid>() || g.isType<vdb::DoubleGrid>())
        return g.getGridClass() == vdb::GRID_LEVEL_SET ? Kind::LevelSet : Kind::Fog;
    if (g.isType<vdb::Int32Grid>() || g.isType<vdb::Int64Grid>()) return Kind::Ids;
    if (g.isType<vdb::BoolGrid>() || g.isType<vdb::MaskGrid>()) return Kind::Mask;
    if (isColourType(g)) return Kind::Colour;
    return std::nullopt;
}

std::string valueTypeOf(const vdb::GridBase& g) { return g.valueType(); }

// ---------------------------------------------------------------------------------------------
// Where source voxels land. Source index i -> oriented j (axis switch: a permutation with signs,
// each voxel's unit cube [i, i+1) mapped onto [j, j+1)) -> world continuous u = j * scale + offset.

Box toBox(const vdb::CoordBBox& b) {
    return {glm::ivec3(b.min().x(), b.min().y(), b.min().z()),
            glm::ivec3(b.max().x(), b.max().y(), b.max().z()) + 1};
}
vdb::CoordBBox toCoordBBox(const Box& b) {
    return vdb::CoordBBox(vdb::Coord(b.min.x, b.min.y, b.min.z), vdb::Coord(b.max.x - 1, b.max.y - 1, b.max.z - 1));
}
// Widened to whole leaves: OpenVDB's clip turns every tile that a clip box cuts into a dense leaf
// (2 KiB for floats), so an unaligned box would fill its whole boundary with leaves.
vdb::CoordBBox leafAligned(const Box& b) {
    auto down = [](int v) { return v >= 0 ? v & ~7 : -((-v + 7) & ~7); };
    glm::ivec3 lo(down(b.min.x), down(b.min.y), down(b.min.z));
    glm::ivec3 hi(down(b.max.x + 7), down(b.max.y + 7), down(b.max.z + 7));
    return vdb::CoordBBox(vdb::Coord(lo.x, lo.y, lo.z), vdb::Coord(hi.x - 1, hi.y - 1, hi.z - 1));
}
Box unite(const Box& a, const Box& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}
std::uint64_t volume(const Box& b) {
    if (b.empty()) return 0;
    glm::u64vec3 s(b.size());
    return s.x * s.y * s.z;
}
int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

struct Mapping {
    int perm[3] = {0, 1, 2};  // world axis a reads source axis perm[a]
    int sign[3] = {1, 1, 1};
    glm::dvec3 scale{1.0};    // world voxels per source voxel, per world axis
    glm::dvec3 offset{0.0};   // world position of oriented voxel 0's corner
    bool exact = true;        // scale 1 and whole-voxel offset: a voxel-for-voxel copy

    glm::ivec3 toSource(glm::ivec3 j) const {
        glm::ivec3 i;
        for (int a = 0; a < 3; ++a) i[perm[a]] = sign[a] > 0 ? j[a] : -j[a] - 1;
        return i;
    }
    // Continuous, voxel centres at integers (OpenVDB's index space).
    glm::dvec3 toSourceCentre(glm::dvec3 j) const {
        glm::dvec3 i;
        for (int a = 0; a < 3; ++a) i[perm[a]] = sign[a] > 0 ? j[a] : -j[a] - 1.0;
        return i;
    }
    Box orient(const Box& s) const {
        Box j;
        for (int a = 0; a < 3; ++a) {
            int p = perm[a];
            j.min[a] = sign[a] > 0 ? s.min[p] : -s.max[p];
            j.max[a] = sign[a] > 0 ? s.max[p] : -s.min[p];
        }
        return j;
    }
    Box unorient(const Box& j) const {
        Box s;
        for (int a = 0; a < 3; ++a) {
            int p = perm[a];
            s.min[p] = sign[a] > 0 ? j.min[a] : -j.max[a];
            s.max[p] = sign[a] > 0 ? j.max[a] : -j.min[a];
        }
        return s;
    }
    // World voxels touched by an oriented box, widened by `margin` world voxels.
    Box span(const Box& j, double margin) const {
        Box w;
        for (int a = 0; a < 3; ++a) {
            w.min[a] = int(std::floor(j.min[a] * scale[a] + offset[a] - margin));
            w.max[a] = int(std::ceil(j.max[a] * scale[a] + offset[a] + margin));
        }
        return w;
    }
    // World voxels whose centre lies inside an oriented box, shrunk by `margin` world voxels.
    Box centresInside(const Box& j, double margin) const {
        Box w;
        for (int a = 0; a < 3; ++a) {
            w.min[a] = int(std::ceil(j.min[a] * scale[a] + offset[a] + margin - 0.5));
            w.max[a] = int(std::ceil(j.max[a] * scale[a] + offset[a] - margin - 0.5));
        }
        return w;
    }
    // Oriented voxels any sampling of the world box may read (nearest, footprint or trilinear).
    Box needed(const Box& w) const {
        if (exact) return Box{w.min - glm::ivec3(offset), w.max - glm::ivec3(offset)};
        Box j;
        for (int a = 0; a < 3; ++a) {
            j.min[a] = int(std::floor((w.min[a] - offset[a]) / scale[a])) - 1;
            j.max[a] = int(std::ceil((w.max[a] - offset[a]) / scale[a])) + 2;
        }
        return j;
    }
    // Exact mappings: the world voxel of source voxel i.
    glm::ivec3 exactTarget(glm::ivec3 i) const {
        glm::ivec3 j;
        for (int a = 0; a < 3; ++a) j[a] = sign[a] > 0 ? i[perm[a]] : -i[perm[a]] - 1;
        return j + glm::ivec3(offset);
    }
    glm::ivec3 nearest(glm::ivec3 t) const {
        if (exact) return t - glm::ivec3(offset);
        glm::ivec3 j;
        for (int a = 0; a < 3; ++a) j[a] = int(std::floor((t[a] + 0.5 - offset[a]) / scale[a]));
        return j;
    }
    glm::dvec3 centre(glm::ivec3 t) const {  // oriented, continuous, voxel centres at integers
        glm::dvec3 x;
        for (int a = 0; a < 3; ++a) x[a] = (t[a] + 0.5 - offset[a]) / scale[a] - 0.5;
        return x;
    }
    // Oriented voxels whose centres lie in world voxel t (inclusive); the nearest one on axes
    // where the world is finer than the source.
    void footprint(glm::ivec3 t, glm::ivec3& lo, glm::ivec3& hi) const {
        glm::ivec3 n = nearest(t);
        for (int a = 0; a < 3; ++a) {
            lo[a] = int(std::ceil((t[a] - offset[a]) / scale[a] - 0.5));
            hi[a] = int(std::ceil((t[a] + 1 - offset[a]) / scale[a] - 0.5)) - 1;
            if (hi[a] < lo[a]) lo[a] = hi[a] = n[a];
        }
    }
};

// ---------------------------------------------------------------------------------------------

enum CellMark : std::uint8_t { kCellNone = 0, kCellUniform = 1, kCellSample = 2 };

// Calls f for each active voxel of a streamed leaf that lies in `box` (OpenVDB's leaf order: z fastest).
template <typename F>
void forLeafVoxels(const vdb::Coord& origin, const Sample* samples, const Box& box, F&& f) {
    for (int i = 0; i < 512; ++i) {
        if (!samples[i].active) continue;
        const glm::ivec3 p(origin.x() + (i >> 6), origin.y() + ((i >> 3) & 7), origin.z() + (i & 7));
        if (box.contains(p)) f(samples[i]);
    }
}

bool isColourName(std::string name) {
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    return name == "color" || name == "colour" || name == "cd" || name == "albedo" || name == "rgb";
}

std::string metaString(const vdb::MetaMap& m, const char* key) {
    auto s = vdb::DynamicPtrCast<const vdb::StringMetadata>(m[key]);
    return s ? s->value() : std::string();
}

glm::vec3 idColour(std::int64_t v) {
    // Distinct, pleasant colours for foreign ids: golden-ratio hue steps, fixed saturation/value.
    double h = std::fmod(double(v) * 0.61803398875 + 0.1, 1.0);
    if (h < 0) h += 1.0;
    glm::vec3 rgb = glm::clamp(glm::abs(glm::mod(glm::vec3(float(h) * 6.0f) + glm::vec3(0, 4, 2), 6.0f) - 3.0f) - 1.0f,
                               0.0f, 1.0f);
    return glm::mix(glm::vec3(1.0f), rgb, 0.55f) * 0.8f;
}

std::vector<world::Material> defaultHeightMaterials() {
    return {{"height_0", {0.30f, 0.24f, 0.18f}, glm::vec3(0.0f), 0.0f},
            {"height_1", {0.25f, 0.42f, 0.16f}, glm::vec3(0.0f), 0.0f},
            {"height_2", {0.45f, 0.45f, 0.47f}, glm::vec3(0.0f), 0.0f},
            {"height_3", {0.90f, 0.90f, 0.92f}, glm::vec3(0.0f), 0.0f}};
}

// One import, from the plan to the last slab.
class Importer {
public:
    Importer(const fs::path& path, const VdbImportOptions& options)
        : mPath(path), mFile(path.string()), mOptions(options), mReader(path) {}

    // target: the scene an importVdbInto() writes into; null for a new world.
    void plan(const world::Scene* target);
    void run(world::Scene& scene, bool intoExisting);
    VdbImportReport& report() { return mReport; }

private:
    void selectGrid();
    void checkTransform(const vdb::GridBase& g);
    void selectColourGrid();
    void readTopology();
    void readColourTopology();
    void forEachSolidTile(const SourceGrid& topology, const std::function<void(const Box&, const Sample&)>& f) const;
    void placeAxesAndScale();
    void placeOffset(const world::Scene* target);
    void readTopologyStreaming();
    template <typename TreeT>
    void readTopologyStreamingTyped();
    template <typename OnUniform>
    void markCells(const SourceGrid& topology, std::vector<std::uint8_t>& marks, OnUniform&& onUniform);
    void makeSlabs(const std::vector<std::uint8_t>& marks);
    void estimate(const world::Scene* target);
    void buildPalette();
    // Streaming: a voxel-for-voxel copy read leaf by leaf in file order, never building an
    // OpenVDB tree (io/vdb_tree_stream.h). Solid tiles come first, then each leaf's voxels.
    bool decideStreaming() const;
    void streamPass(const std::function<void(const Box&, const Sample&)>& onTile,
                    const std::function<void(const vdb::Coord&, const Sample*)>& onLeaf);
    template <typename TreeT>
    void streamPassTyped(const std::function<void(const Box&, const Sample&)>& onTile,
                         const std::function<void(const vdb::Coord&, const Sample*)>& onLeaf);
    void writeTileRegion(BrickGrid& grid, const Box& source, const Sample& s);
    void writeLeaf(BrickGrid& grid, const vdb::Coord& origin, const Sample* samples);
    void noteWrite(BrickGrid& grid);
    void scanActive(std::size_t index, const std::vector<Box>& leaves, const Box& region,
                    const std::function<void(const Sample&)>& f);
    bool solidAt(glm::ivec3 t, Sample& s) const;
    bool solid(const Sample& s) const;
    int materialFor(glm::ivec3 t, const Sample& s);  // index into mMaterials
    int colourMaterial(glm::vec3 colour, std::uint64_t voxels = 1);
    bool uniformMaterial(const Sample& tile, const Box& cellBox, int& material);
    int heightBand(int y) const;
    glm::vec3 colourAt(glm::ivec3 t) const;

    fs::path mPath;
    std::string mFile;
    const VdbImportOptions& mOptions;
    VdbReader mReader;
    VdbImportReport mReport;
    VdbImportPlan& mPlan = mReport.plan;

    bool mOwn = false;
    vdb_layout::WorldHeader mWorldHeader;
    std::size_t mGridIndex = 0;
    vdb::GridBase::Ptr mGridHeader;
    Kind mKind = Kind::Fog;
    MaterialRule mRule = MaterialRule::Constant;
    std::unique_ptr<SourceGrid> mShape;
    int mColourIndex = -1;  // separate colour grid, or -1
    std::unique_ptr<SourceGrid> mColour;
    vdb::math::Transform::Ptr mShapeXform, mColourXform;
    bool mSameXform = true;
    bool mTrilinear = false;   // level set, finer world on every axis
    bool mFootprint = false;   // level set, coarser world on some axis
    bool mStreaming = false;   // see streamPass()
    int mWritesSinceClear = 0;

    Mapping mMap;
    Box mSourceBox;  // source index box imported
    Box mWorldBox;   // where it lands, clipped to the world
    glm::ivec3 mWorldSize{0};
    std::vector<Box> mLeaves;       // source leaf boxes (clipped to mSourceBox)
    std::vector<Box> mColourLeaves; // colour grid leaf boxes
    std::uint64_t mShapeTopologyBytes = 0, mColourTopologyBytes = 0;
    std::uint64_t mShapeLeafBytes = 0, mColourLeafBytes = 0;
    struct Slab {
        int cz0, cz1;  // world cell z range
        std::uint64_t leaves;
    };
    std::vector<Slab> mSlabs;
    std::uint64_t mSlabLeavesMax = 0;

    // Materials of the import, index 0 unused; mRemap maps them into the scene's palette.
    std::vector<world::Material> mMaterials;
    std::vector<MaterialId> mRemap;
    std::unordered_map<std::int64_t, int> mIdLut;
    std::unique_ptr<ColourMapper> mMapper;
    ColourError mColourError;
    int mHeightBands = 0;
};

void Importer::plan(const world::Scene* target) {
    mPlan.file = mFile;
    mPlan.budgetBytes = mOptions.memoryBudgetBytes;
    mOwn = vdb_layout::isVoxengineFile(mReader.fileMetadata());
    if (mOwn) {
        auto h = vdb_layout::readWorldMetadata(mReader.fileMetadata(), mFile);
        if (!h) throw ImportFailure{h.error().message};
        mWorldHeader = std::move(*h);
    }
    selectGrid();
    selectColourGrid();
    placeAxesAndScale();
    mStreaming = decideStreaming();
    mPlan.streamed = mStreaming;
    if (mStreaming) readTopologyStreaming();
    else readTopology();  // leaves mShape holding the topology
    placeOffset(target);
    if (mStreaming) {
        // Leaves give the cells that need voxels; tiles were counted while streaming.
        std::vector<std::uint8_t> marks(std::size_t(volume(Box{glm::ivec3(0), (mWorldSize + 7) / 8})), kCellNone);
        const glm::ivec3 cells = (mWorldSize + 7) / 8;
        for (const Box& leaf : mLeaves) {
            Box w = mMap.span(mMap.orient(leaf), 0.0).intersect(mWorldBox);
            if (w.empty()) continue;
            for (int z = w.min.z >> 3; z <= (w.max.z - 1) >> 3; ++z)
                for (int y = w.min.y >> 3; y <= (w.max.y - 1) >> 3; ++y)
                    for (int x = w.min.x >> 3; x <= (w.max.x - 1) >> 3; ++x) {
                        std::uint8_t& m = marks[std::size_t(x) + std::size_t(cells.x) * (std::size_t(y) + std::size_t(cells.y) * std::size_t(z))];
                        mPlan.sampledCells += (m == kCellNone);
                        m = kCellSample;
                    }
        }
        mLeaves = {};  // the import streams the leaves again
    } else {
        std::vector<std::uint8_t> marks(std::size_t(volume(Box{glm::ivec3(0), (mWorldSize + 7) / 8})), kCellNone);
        // Counting pass: which cells need voxels, which fill whole from tiles.
        markCells(*mShape, marks, [&](glm::ivec3, int) {});
        for (std::uint8_t m : marks) {
            mPlan.sampledCells += (m == kCellSample);
            mPlan.uniformCells += (m == kCellUniform);
        }
        mShape->attach(nullptr);
        readColourTopology();
        makeSlabs(marks);
    }
    estimate(target);
}

void Importer::selectGrid() {
    const auto& entries = mReader.grids();
    if (entries.empty()) failImport("{}: the file holds no grids", mFile);
    auto describe = [&](std::size_t i, const vdb::GridBase* g, const char* state) {
        return fmt::format("{} ({}{}{})", entries[i].name, g ? valueTypeOf(*g) : entries[i].type, *state ? ", " : "",
                           state);
    };
    std::vector<vdb::GridBase::Ptr> headers(entries.size());
    auto header = [&](std::size_t i) -> vdb::GridBase::Ptr {
        if (!headers[i] && vdb::GridBase::isRegistered(entries[i].type)) headers[i] = mReader.readHeader(i);
        return headers[i];
    };
    auto isEmpty = [&](std::size_t i) {
        // OpenVDB writers store the active voxel count as metadata; read the topology otherwise.
        vdb::GridBase::Ptr g = header(i);
        if (auto count = vdb::DynamicPtrCast<const vdb::Int64Metadata>((*g)[vdb::GridBase::META_FILE_VOXEL_COUNT]))
            if (count->value() > 0) return false;
        vdb::GridBase::Ptr t = mReader.readTopology(i);
        if (t->activeVoxelCount() > 0) return false;
        // A level set may be all interior tiles (inactive, negative).
        if (kindOf(*t) == Kind::LevelSet) {
            auto source = makeSource(*t);
            source->attach(t);
            bool inside = false;
            source->forEachTile([&](const vdb::CoordBBox&, const Sample& s) { inside |= s.scalar < 0.0; });
            return !inside && t->baseTree().leafCount() == 0;
        }
        return true;
    };

    int chosen = -1;
    if (!mOptions.grid.empty()) {
        chosen = mReader.find(mOptions.grid);
        if (chosen < 0) {
            std::string names;
            for (const auto& e : entries) names += (names.empty() ? "" : ", ") + e.name;
            failImport("{}: no grid named '{}' (grids: {})", mFile, mOptions.grid, names);
        }
        vdb::GridBase::Ptr g = header(std::size_t(chosen));
        if (!g || !kindOf(*g))
            failImport("{}: grid '{}' has type {}, which cannot be imported (usable: float/double level sets and fog "
                       "volumes, int32/int64 ids, bool/mask, vec3 colours)",
                       mFile, mOptions.grid, g ? valueTypeOf(*g) : entries[std::size_t(chosen)].type);
        if (isEmpty(std::size_t(chosen))) failImport("{}: grid '{}' is empty (no active voxels)", mFile, mOptions.grid);
    } else if (mOwn) {
        chosen = mReader.find(vdb_layout::kMaterialGrid);
        if (chosen < 0) failImport("{}: voxengine file without its '{}' grid", mFile, vdb_layout::kMaterialGrid);
    } else {
        // The first usable non-empty grid, scalar grids before vec3 ones.
        std::vector<std::string> why;
        for (int pass = 0; pass < 2 && chosen < 0; ++pass) {
            for (std::size_t i = 0; i < entries.size() && chosen < 0; ++i) {
                vdb::GridBase::Ptr g = header(i);
                if (!g || !kindOf(*g)) {
                    if (pass == 0) why.push_back(describe(i, g.get(), "unusable type"));
                    continue;
                }
                if ((kindOf(*g) == Kind::Colour) != (pass == 1)) continue;
                if (isEmpty(i)) {
                    why.push_back(describe(i, g.get(), "empty"));
                    continue;
                }
                chosen = int(i);
            }
        }
        if (chosen < 0) {
            std::string list;
            for (const auto& w : why) list += (list.empty() ? "" : ", ") + w;
            failImport("{}: nothing to import: no grid is both usable and non-empty ({})", mFile, list);
        }
    }
    mGridIndex = std::size_t(chosen);
    mGridHeader = header(mGridIndex);
    mKind = *kindOf(*mGridHeader);
    if (mOwn && entries[mGridIndex].name == vdb_layout::kMaterialGrid && mGridHeader->isType<vdb::Int32Grid>())
        mKind = Kind::VoxIds;
    checkTransform(*mGridHeader);
    mShapeXform = mGridHeader->transformPtr();
    mPlan.grid = entries[mGridIndex].name;
    mPlan.gridType = valueTypeOf(*mGridHeader);
    mPlan.gridClass = vdb::GridBase::gridClassToString(mGridHeader->getGridClass());
    mPlan.kind = kindName(mKind);
    mPlan.voxengine = mOwn;
}

void Importer::checkTransform(const vdb::GridBase& g) {
    const vdb::math::Transform& xf = g.transform();
    const std::string name = g.getName();
    if (!xf.isLinear())
        failImport("{}: grid '{}' has a non-linear ({}) transform; only axis-aligned scale and translation can be "
                   "imported",
                   mFile, name, xf.mapType());
    vdb::Mat4d m = xf.baseMap()->getAffineMap()->getMat4();
    double largest = 0.0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(m(r, c)));
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(m(r, c))) failImport("{}: grid '{}' has a transform that is not finite", mFile, name);
            if (r != c && std::abs(m(r, c)) > 1e-6 * largest)
                failImport("{}: grid '{}' has a rotated or sheared transform; only axis-aligned scale and translation "
                           "can be imported",
                           mFile, name);
        }
        if (!(m(r, r) > 0.0))
            failImport("{}: grid '{}' has a mirrored or degenerate transform (scale {} on axis {})", mFile, name,
                       m(r, r), "xyz"[r]);
    }
}

void Importer::selectColourGrid() {
    const auto& entries = mReader.grids();
    MaterialRule rule = mOptions.rule;
    const bool wantColour = rule == MaterialRule::Colour || rule == MaterialRule::Auto;
    if (wantColour && mKind != Kind::Colour && mKind != Kind::Ids && mKind != Kind::VoxIds) {
        int found = -1;
        if (!mOptions.colourGrid.empty()) {
            found = mReader.find(mOptions.colourGrid);
            if (found < 0) failImport("{}: no colour grid named '{}'", mFile, mOptions.colourGrid);
        } else {
            for (std::size_t i = 0; i < entries.size() && found < 0; ++i)
                if (i != mGridIndex && isColourName(entries[i].name)) found = int(i);
        }
        if (found >= 0) {
            if (!vdb::GridBase::isRegistered(entries[std::size_t(found)].type))
                failImport("{}: colour grid '{}' has the unknown type {}", mFile, entries[std::size_t(found)].name,
                           entries[std::size_t(found)].type);
            vdb::GridBase::Ptr h = mReader.readHeader(std::size_t(found));
            if (isColourType(*h)) {
                mColourIndex = found;
                mColourXform = h->transformPtr();
                mSameXform = *mColourXform == *mShapeXform;
                mPlan.colourGrid = entries[std::size_t(found)].name;
            } else if (!mOptions.colourGrid.empty()) {
                failImport("{}: colour grid '{}' has type {}, not vec3", mFile, mOptions.colourGrid, valueTypeOf(*h));
            }
        }
    }
    switch (rule) {
        case MaterialRule::Auto:
            if (mKind == Kind::VoxIds || mKind == Kind::Ids) mRule = MaterialRule::Ids;
            else if (mKind == Kind::Colour || mColourIndex >= 0) mRule = MaterialRule::Colour;
            else mRule = MaterialRule::Constant;
            break;
        case MaterialRule::Ids:
            if (mKind != Kind::VoxIds && mKind != Kind::Ids)
                failImport("{}: the ids rule needs an integer grid; '{}' is {}", mFile, mPlan.grid, mPlan.gridType);
            mRule = rule;
            break;
        case MaterialRule::Colour:
            if (mKind != Kind::Colour && mColourIndex < 0)
                failImport("{}: the colour rule needs a vec3 colour grid (name one with --colour-grid)", mFile);
            mRule = rule;
            break;
        default: mRule = rule;
    }
    if (mRule == MaterialRule::Height) {
        mHeightBands = int(mOptions.heightMaterials.empty() ? 4 : mOptions.heightMaterials.size());
    }
    switch (mRule) {
        case MaterialRule::Ids:
            mPlan.rule = mKind == Kind::VoxIds ? "the file's palette (exact)" : "one material per distinct value";
            break;
        case MaterialRule::Colour:
            mPlan.rule = fmt::format("colours of '{}' quantised to at most {} materials",
                                     mColourIndex >= 0 ? entries[std::size_t(mColourIndex)].name : mPlan.grid,
                                     mOptions.maxColours);
            break;
        case MaterialRule::Height: mPlan.rule = fmt::format("{} bands by height", mHeightBands); break;
        default: mPlan.rule = fmt::format("constant '{}'", mOptions.material.name);
    }
    if (mOptions.maxColours < 1 || std::size_t(mOptions.maxColours) >= world::kMaxMaterials)
        failImport("{}: the colour count must be in 1..{}", mFile, world::kMaxMaterials - 1);
}

void Importer::readTopology() {
    mShape = makeSource(*mGridHeader);
    mShape->attach(mReader.readTopology(mGridIndex));
    vdb::GridBase::ConstPtr g = mShape->base();
    mPlan.sourceActiveVoxels = g->activeVoxelCount();
    mShapeTopologyBytes = g->memUsage();

    // Extent of what is solid: active voxels, and for level sets every leaf and inside tile.
    Box content;
    vdb::CoordBBox active = g->evalActiveVoxelBoundingBox();
    if (!active.empty()) content = toBox(active);
    Box crop = mOptions.crop ? *mOptions.crop : Box{glm::ivec3(INT32_MIN / 2), glm::ivec3(INT32_MAX / 2)};
    std::uint64_t leafCount = 0;
    mShape->forEachLeaf([&](const vdb::CoordBBox& node, std::uint64_t on) {
        ++leafCount;
        if (mKind != Kind::LevelSet && on == 0) return;
        Box b = toBox(node).intersect(crop);
        if (b.empty()) return;
        if (mKind == Kind::LevelSet) content = unite(content, b);
        mLeaves.push_back(b);
    });
    mShape->forEachTile([&](const vdb::CoordBBox&, const Sample&) { mPlan.sourceTiles++; });
    forEachSolidTile(*mShape, [&](const Box& b, const Sample&) { content = unite(content, b); });
    mPlan.sourceLeaves = leafCount;
    mLeaves.shrink_to_fit();
    // Bytes of one loaded leaf: values plus the node (mask, origin, buffer header).
    std::uint64_t valueBytes = mKind == Kind::Colour ? 12 : 4;
    if (mGridHeader->isType<vdb::DoubleGrid>() || mGridHeader->isType<vdb::Int64Grid>()) valueBytes = 8;
    if (mGridHeader->isType<vdb::Vec3DGrid>()) valueBytes = 24;
    if (mKind == Kind::Mask) valueBytes = 0;
    mShapeLeafBytes = 512 * valueBytes + 128;

    mSourceBox = content.intersect(crop);
    if (mSourceBox.empty() && mOwn && !mOptions.crop) mSourceBox = Box{glm::ivec3(0), glm::ivec3(1)};  // an all-air world
    if (mSourceBox.empty()) {
        if (mOptions.crop) failImport("{}: nothing of grid '{}' lies inside the crop box", mFile, mPlan.grid);
        failImport("{}: grid '{}' is empty (no active voxels)", mFile, mPlan.grid);
    }
    mPlan.sourceBox = mSourceBox;
}

void Importer::forEachSolidTile(const SourceGrid& topology, const std::function<void(const Box&, const Sample&)>& f) const {
    const Box crop = mOptions.crop ? *mOptions.crop : Box{glm::ivec3(INT32_MIN / 2), glm::ivec3(INT32_MAX / 2)};
    topology.forEachTile([&](const vdb::CoordBBox& box, const Sample& s) {
        if (!solid(s)) return;
        Box b = toBox(box).intersect(crop);
        if (!b.empty()) f(b, s);
    });
}

void Importer::readTopologyStreaming() {
    const vdb::GridBase& g = *mGridHeader;
    if (g.isType<vdb::FloatGrid>()) return readTopologyStreamingTyped<vdb::FloatTree>();
    if (g.isType<vdb::DoubleGrid>()) return readTopologyStreamingTyped<vdb::DoubleTree>();
    if (g.isType<vdb::Int32Grid>()) return readTopologyStreamingTyped<vdb::Int32Tree>();
    if (g.isType<vdb::Int64Grid>()) return readTopologyStreamingTyped<vdb::Int64Tree>();
    if (g.isType<vdb::Vec3SGrid>()) return readTopologyStreamingTyped<vdb::Vec3STree>();
    if (g.isType<vdb::Vec3DGrid>()) return readTopologyStreamingTyped<vdb::Vec3DTree>();
    throw vdb::TypeError("grid type cannot be streamed");
}

// readTopology() without an OpenVDB tree: the same figures from one walk over the nodes.
template <typename TreeT>
void Importer::readTopologyStreamingTyped() {
    using Stream = TreeStream<TreeT>;
    using ValueT = typename TreeT::ValueType;
    const Box crop = mOptions.crop ? *mOptions.crop : Box{glm::ivec3(INT32_MIN / 2), glm::ivec3(INT32_MAX / 2)};
    vdb::GridBase::Ptr header = mReader.openTree(mGridIndex);
    const bool half = header->saveFloatAsHalf();
    std::istream& topology = mReader.stream();
    Box content;
    auto tile = [&](const vdb::CoordBBox& box, const ValueT& value, bool active) {
        mPlan.sourceTiles++;
        const Sample s = toSample(value, active);
        if (active) mPlan.sourceActiveVoxels += volume(toBox(box));
        if (!solid(s)) return;
        const Box b = toBox(box).intersect(crop);
        if (b.empty()) return;
        content = unite(content, b);
        mPlan.uniformCells += volume(b) / world::kBrickVoxels;
    };
    const typename Stream::Root root = Stream::walk(topology, mReader.formatVersion(), half, mReader.fileBytes(), nullptr, tile);
    Stream::stream(topology, nullptr, mReader.formatVersion(), half, root, tile,
                   [&](const vdb::Coord& origin, const typename Stream::LeafMask& mask) {
                       mPlan.sourceLeaves++;
                       const std::uint64_t on = mask.countOn();
                       mPlan.sourceActiveVoxels += on;
                       const glm::ivec3 o(origin.x(), origin.y(), origin.z());
                       Box b;
                       if (mKind == Kind::LevelSet) {
                           b = Box{o, o + 8};
                       } else if (on) {
                           b = Box{glm::ivec3(INT32_MAX), glm::ivec3(INT32_MIN)};
                           for (auto it = mask.beginOn(); it; ++it) {
                               const vdb::Index i = it.pos();
                               const glm::ivec3 p = o + glm::ivec3(int(i >> 6), int((i >> 3) & 7), int(i & 7));
                               b.min = glm::min(b.min, p);
                               b.max = glm::max(b.max, p + 1);
                           }
                       }
                       b = b.intersect(crop);
                       if (!b.empty()) {
                           content = unite(content, b);
                           mLeaves.push_back(b);
                       }
                       return false;  // planning needs no values
                   },
                   {});
    mLeaves.shrink_to_fit();
    mSourceBox = content.intersect(crop);
    if (mSourceBox.empty() && mOwn && !mOptions.crop) mSourceBox = Box{glm::ivec3(0), glm::ivec3(1)};  // an all-air world
    if (mSourceBox.empty()) {
        if (mOptions.crop) failImport("{}: nothing of grid '{}' lies inside the crop box", mFile, mPlan.grid);
        failImport("{}: grid '{}' is empty (no active voxels)", mFile, mPlan.grid);
    }
    mPlan.sourceBox = mSourceBox;
}

void Importer::readColourTopology() {
    if (mColourIndex >= 0) {
        mColour = makeSource(*mReader.readHeader(std::size_t(mColourIndex)));
        mColour->attach(mReader.readTopology(std::size_t(mColourIndex)));
        mColourTopologyBytes = mColour->base()->memUsage();
        mColour->forEachLeaf([&](const vdb::CoordBBox& node, std::uint64_t on) {
            if (on) mColourLeaves.push_back(toBox(node));
        });
        mColourLeafBytes = 512 * (mColour->base()->isType<vdb::Vec3DGrid>() ? 24 : 12) + 128;
        mColour->attach(nullptr);
    }
}

void Importer::placeAxesAndScale() {
    const std::string creatorFile = metaString(mReader.fileMetadata(), "creator");
    const std::string creatorGrid = metaString(*mGridHeader, "creator");
    bool upZ = mOptions.up == UpAxis::Z;
    if (mOptions.up == UpAxis::Auto && !mOwn)
        upZ = creatorFile.find("Blender") != std::string::npos || creatorGrid.find("Blender") != std::string::npos;
    mPlan.upZ = upZ;
    if (upZ) {
        // Z-up to Y-up, a rotation about x: (x, y, z) -> (x, z, -y).
        mMap.perm[0] = 0, mMap.perm[1] = 2, mMap.perm[2] = 1;
        mMap.sign[0] = 1, mMap.sign[1] = 1, mMap.sign[2] = -1;
        if (mOptions.up == UpAxis::Auto) mPlan.notes.push_back("Z-up (the file was written by Blender); --up y to keep its axes");
    }

    vdb::Vec3d vs = mShapeXform->voxelSize();
    mPlan.sourceVoxelSize = glm::dvec3(vs.x(), vs.y(), vs.z());
    double smallest = std::min({vs.x(), vs.y(), vs.z()});
    double target_ = mOptions.voxelSize > 0.0f ? double(mOptions.voxelSize) : smallest;
    if (mOwn && mOptions.voxelSize <= 0.0f) target_ = vs.x();
    mPlan.voxelSize = target_;
    bool uniform = std::abs(vs.x() - vs.y()) <= 1e-6 * smallest && std::abs(vs.x() - vs.z()) <= 1e-6 * smallest;
    if (!uniform && mOptions.voxelSize <= 0.0f)
        mPlan.notes.push_back(fmt::format("voxels are {:.4g} x {:.4g} x {:.4g}: resampled to a uniform {:.4g}", vs.x(),
                                          vs.y(), vs.z(), target_));
    for (int a = 0; a < 3; ++a) {
        double s = vs[mMap.perm[a]] / target_;
        if (std::abs(s - 1.0) < 1e-9) s = 1.0;
        if (!(s >= 1.0 / 64.0 && s <= 64.0))
            failImport("{}: resampling by {:.4g}x on an axis is outside 1/64..64 (voxel size {:.4g} to {:.4g})", mFile,
                       s, vs[mMap.perm[a]], target_);
        mMap.scale[a] = s;
    }
    mPlan.scale = mMap.scale;
    const bool unitScale = mMap.scale == glm::dvec3(1.0);
    if (mKind == Kind::LevelSet && !unitScale) {
        mTrilinear = glm::all(glm::greaterThanEqual(mMap.scale, glm::dvec3(1.0)));
        mFootprint = !mTrilinear;
        mPlan.notes.push_back(mTrilinear ? "level set resampled finer: inside where the trilinear distance < 0"
                                         : "level set resampled coarser: conservative (solid if any source voxel in it is)");
    }
}

void Importer::placeOffset(const world::Scene* target) {
    const bool upZ = mPlan.upZ;
    const bool unitScale = mMap.scale == glm::dvec3(1.0);

    Box oriented = mMap.orient(mSourceBox);
    if (mOptions.offset) {
        mMap.offset = glm::dvec3(*mOptions.offset);
    } else if (mOwn && unitScale && !upZ && !mOptions.crop) {
        mMap.offset = glm::dvec3(0.0);  // our own files keep their coordinates
    } else if (unitScale) {
        // Smallest offset that lands everything at >= 0 with source leaves on our cells, so the
        // source's tiles and leaves map one to one onto homogeneous cells and bricks.
        for (int a = 0; a < 3; ++a) mMap.offset[a] = -double(floorDiv(oriented.min[a], 8) * 8);
    } else {
        for (int a = 0; a < 3; ++a) mMap.offset[a] = -oriented.min[a] * mMap.scale[a];
    }
    mMap.exact = unitScale && mMap.offset == glm::floor(mMap.offset);
    mPlan.offset = mMap.offset;

    Box landed = mMap.span(oriented, 0.0);
    if (target) {
        mWorldSize = target->grid.sizeInVoxels();
    } else if (mOwn && mMap.exact && mMap.offset == glm::dvec3(0.0) && !upZ) {
        mWorldSize = mWorldHeader.size;
    } else {
        mWorldSize = glm::max(landed.max, glm::ivec3(1));
        glm::u64vec3 cells = glm::u64vec3((glm::dvec3(mWorldSize) + 7.0) / 8.0);
        if (glm::any(glm::greaterThan(mWorldSize, glm::ivec3(world::kMaxWorldExtent))) ||
            cells.x * cells.y * cells.z > world::kMaxTopGridCells)
            failImport("{}: the import would make a world of {}x{}x{} voxels, over the engine's limit ({} per axis, {} "
                       "top-grid cells); use --voxel-size or --crop",
                       mFile, mWorldSize.x, mWorldSize.y, mWorldSize.z, world::kMaxWorldExtent, world::kMaxTopGridCells);
    }
    mWorldBox = landed.intersect(Box{glm::ivec3(0), mWorldSize});
    if (mWorldBox.empty())
        failImport("{}: nothing of grid '{}' lands inside the world (check --offset and --crop)", mFile, mPlan.grid);
    if (landed.min != mWorldBox.min || landed.max != mWorldBox.max)
        mPlan.notes.push_back("part of the grid lands outside the world and is cut off");
    mPlan.worldBox = mWorldBox;
    mPlan.worldSize = ((mWorldSize + 7) / 8) * 8;
}

// Marks cells to sample (touched by a leaf, or by a tile only in part) and reports cells a solid
// tile covers whole, with a material that cannot vary inside the cell, through onUniform.
template <typename OnUniform>
void Importer::markCells(const SourceGrid& topology, std::vector<std::uint8_t>& marks, OnUniform&& onUniform) {
    const glm::ivec3 cells = (mWorldSize + 7) / 8;
    auto cellIndex = [&](glm::ivec3 c) { return std::size_t(c.x) + std::size_t(cells.x) * (std::size_t(c.y) + std::size_t(cells.y) * std::size_t(c.z)); };
    const double margin = mTrilinear ? std::max({mMap.scale.x, mMap.scale.y, mMap.scale.z}) : 0.0;
    auto cellRange = [&](const Box& w, glm::ivec3& lo, glm::ivec3& hi) {
        Box clipped = w.intersect(mWorldBox);
        if (clipped.empty()) return false;
        lo = clipped.min >> 3;
        hi = (clipped.max - 1) >> 3;
        return true;
    };
    for (const Box& leaf : mLeaves) {
        glm::ivec3 lo, hi;
        if (!cellRange(mMap.span(mMap.orient(leaf), margin), lo, hi)) continue;
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) marks[cellIndex({x, y, z})] = kCellSample;
    }
    forEachSolidTile(topology, [&](const Box& tileBox, const Sample& tileValue) {
        Box oriented = mMap.orient(tileBox);
        Box inside = mMap.centresInside(oriented, margin);
        glm::ivec3 lo, hi;
        if (!cellRange(mMap.span(oriented, margin), lo, hi)) return;
        for (int z = lo.z; z <= hi.z; ++z) {
            for (int y = lo.y; y <= hi.y; ++y) {
                for (int x = lo.x; x <= hi.x; ++x) {
                    const glm::ivec3 c(x, y, z);
                    std::uint8_t& m = marks[cellIndex(c)];
                    if (m == kCellSample) continue;
                    Box cellBox{c * 8, c * 8 + 8};
                    // Whole cell inside the tile and inside the world box: no voxel to read.
                    bool whole = glm::all(glm::greaterThanEqual(cellBox.min, glm::max(inside.min, mWorldBox.min))) &&
                                 glm::all(glm::lessThanEqual(cellBox.max, glm::min(inside.max, mWorldBox.max)));
                    int material = 0;
                    if (whole && uniformMaterial(tileValue, cellBox, material)) {
                        m = kCellUniform;
                        onUniform(c, material);
                    } else {
                        m = kCellSample;
                    }
                }
            }
        }
    });
}

void Importer::makeSlabs(const std::vector<std::uint8_t>& marks) {
    // Leaves each cell-z layer needs; slabs of consecutive layers hold about 1/16 of the leaves
    // (at least 1024), so the source's values are read in bounded pieces.
    const glm::ivec3 cells = (mWorldSize + 7) / 8;
    std::vector<std::uint64_t> perLayer(std::size_t(cells.z) + 1, 0);
    const double margin = mTrilinear ? std::max({mMap.scale.x, mMap.scale.y, mMap.scale.z}) : 0.0;
    for (const Box& leaf : mLeaves) {
        Box w = mMap.span(mMap.orient(leaf), margin).intersect(mWorldBox);
        if (w.empty()) continue;
        for (int z = w.min.z >> 3; z <= (w.max.z - 1) >> 3; ++z) perLayer[std::size_t(z)]++;
    }
    std::vector<std::uint8_t> layerHasSamples(std::size_t(cells.z), 0);
    const std::size_t layer = std::size_t(cells.x) * std::size_t(cells.y);
    for (std::size_t i = 0; i < marks.size(); ++i)
        if (marks[i] == kCellSample) layerHasSamples[i / layer] = 1;
    const std::uint64_t limit = std::max<std::uint64_t>(1024, (mLeaves.size() + 15) / 16);
    int start = -1;
    std::uint64_t count = 0;
    for (int z = 0; z <= cells.z; ++z) {
        bool has = z < cells.z && layerHasSamples[std::size_t(z)];
        if (start >= 0 && (!has || count + perLayer[std::size_t(z)] > limit)) {
            mSlabs.push_back({start, z, count});
            start = -1;
            count = 0;
        }
        if (has) {
            if (start < 0) start = z;
            count += perLayer[std::size_t(z)];
        }
    }
    for (const Slab& s : mSlabs) mSlabLeavesMax = std::max(mSlabLeavesMax, s.leaves);
    mPlan.slabs = int(mSlabs.size());
}

void Importer::estimate(const world::Scene* target) {
    constexpr std::uint64_t kBrickBytes = sizeof(world::BrickVoxels) + sizeof(world::BrickMask) + 1;
    const glm::u64vec3 cells = glm::u64vec3((mWorldSize + 7) / 8);
    const std::uint64_t cellCount = cells.x * cells.y * cells.z;
    std::uint64_t worldBytes = target ? 0 : cellCount * (4 + 1);  // top grid and its dirty flags
    worldBytes += cellCount;                                      // the marks
    worldBytes += cells.x * cells.y * 8 * 2;                      // per-slab dirty lists
    std::uint64_t existing = target ? target->grid.liveBricks() : 0;
    worldBytes += (existing + mPlan.sampledCells) * kBrickBytes;  // the pool, reserved at once
    // Each slab read rebuilds the source's topology (nodes, masks, tiles) next to that slab's leaf
    // values; malloc adds a header to every node, hence the 1.25.
    std::uint64_t source = (mShapeTopologyBytes * 5) / 4 + mSlabLeavesMax * mShapeLeafBytes +
                           mLeaves.capacity() * sizeof(Box);
    if (mColour)
        source += (mColourTopologyBytes * 5) / 4 + mColourLeafBytes * std::min<std::uint64_t>(mColourLeaves.size(), 2 * mSlabLeavesMax) +
                  mColourLeaves.capacity() * sizeof(Box);
    if (mRule == MaterialRule::Colour) source += 65536 * 96;  // histogram and mapper memo
    source += 1 << 20;  // the reader: stream buffer, descriptors, file metadata
    if (mStreaming) {
        // No OpenVDB tree is built, neither for planning nor for the import.
        source = 2 << 20;  // node masks on one path, one leaf's values, two stream buffers
    }
    mPlan.worldBytes = worldBytes;
    mPlan.sourceBytes = source;
    mPlan.estimateBytes = worldBytes + source;
    if (mPlan.estimateBytes > mOptions.memoryBudgetBytes)
        failImport("{}: importing grid '{}' would need about {} (world {}x{}x{}: {} for the grid and up to {} bricks; {} "
                   "for the source), over the memory budget of {} (raise it with --memory-budget)",
                   mFile, mPlan.grid, mib(mPlan.estimateBytes), mPlan.worldSize.x, mPlan.worldSize.y, mPlan.worldSize.z,
                   mib(worldBytes), mPlan.sampledCells, mib(source), mib(mOptions.memoryBudgetBytes));
}

bool Importer::solid(const Sample& s) const {
    switch (mKind) {
        case Kind::LevelSet: return s.scalar < 0.0;
        case Kind::Fog: return s.active && s.scalar >= double(mOptions.fogThreshold);
        default: return s.active;
    }
}

int Importer::heightBand(int y) const {
    int span = std::max(1, mWorldBox.max.y - mWorldBox.min.y);
    return std::clamp(int(std::int64_t(y - mWorldBox.min.y) * mHeightBands / span), 0, mHeightBands - 1);
}

bool Importer::uniformMaterial(const Sample& tile, const Box& cellBox, int& material) {
    switch (mRule) {
        case MaterialRule::Constant: material = 1; return true;
        case MaterialRule::Height: {
            int lo = heightBand(cellBox.min.y), hi = heightBand(cellBox.max.y - 1);
            material = 1 + lo;
            return lo == hi;
        }
        case MaterialRule::Colour:
            if (mColourIndex >= 0) return false;  // colours come from another grid: read them
            if (mMapper) material = colourMaterial(tile.colour, world::kBrickVoxels);
            return true;
        case MaterialRule::Ids:
            if (!mMaterials.empty()) material = materialFor(cellBox.min, tile);
            return true;
        default: return false;
    }
}

int Importer::colourMaterial(glm::vec3 colour, std::uint64_t voxels) {
    int index = mMapper->nearest(colour);
    mColourError.add(double(glm::length(clampAlbedo(colour) - mMapper->palette()[std::size_t(index)])), voxels);
    return 1 + index;
}

int Importer::materialFor(glm::ivec3 t, const Sample& s) {
    switch (mRule) {
        case MaterialRule::Constant: return 1;
        case MaterialRule::Height: return 1 + heightBand(t.y);
        case MaterialRule::Colour: return colourMaterial(mColourIndex >= 0 ? colourAt(t) : s.colour);
        case MaterialRule::Ids: {
            const std::int64_t v = std::int64_t(s.scalar);
            if (mKind == Kind::VoxIds) {
                if (v < 1 || std::uint64_t(v) >= mMaterials.size())
                    failImport("{}: corrupt voxengine file: material id {} outside the palette of {}", mFile, v,
                               mMaterials.size() - 1);
                return int(v);
            }
            auto it = mIdLut.find(v);
            if (it == mIdLut.end()) failImport("{}: id {} was not seen while scanning the grid", mFile, v);
            return it->second;
        }
        default: return 1;
    }
}

glm::vec3 Importer::colourAt(glm::ivec3 t) const {
    glm::dvec3 x = mMap.toSourceCentre(mMap.centre(t));
    vdb::Vec3d ijk(x.x, x.y, x.z);
    if (!mSameXform) ijk = mColourXform->worldToIndex(mShapeXform->indexToWorld(ijk));
    return mColour->at(vdb::Coord::round(ijk)).colour;
}

bool Importer::solidAt(glm::ivec3 t, Sample& s) const {
    auto inside = [&](glm::ivec3 i) { return mSourceBox.contains(i); };
    auto coord = [](glm::ivec3 i) { return vdb::Coord(i.x, i.y, i.z); };
    if (mTrilinear) {
        glm::dvec3 x = mMap.toSourceCentre(mMap.centre(t));
        if (!inside(glm::ivec3(glm::round(x)))) return false;
        s.scalar = mShape->trilinear(vdb::Vec3d(x.x, x.y, x.z));
        return s.scalar < 0.0;
    }
    if (mFootprint) {
        glm::ivec3 lo, hi;
        mMap.footprint(t, lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    glm::ivec3 i = mMap.toSource({x, y, z});
                    if (!inside(i)) continue;
                    s = mShape->at(coord(i));
                    if (s.scalar < 0.0) return true;
                }
        return false;
    }
    glm::ivec3 i = mMap.toSource(mMap.nearest(t));
    if (!inside(i)) return false;
    s = mShape->at(coord(i));
    return solid(s);
}

void Importer::scanActive(std::size_t index, const std::vector<Box>& leaves, const Box& region,
                          const std::function<void(const Sample&)>& f) {
    auto sourcePtr = makeSource(*mReader.readHeader(index));
    SourceGrid& source = *sourcePtr;
    // Leaf-aligned z ranges of about 1/8 of the leaves each; a leaf belongs to exactly one.
    std::vector<int> zs;
    for (const Box& b : leaves) zs.push_back(floorDiv(b.min.z, 8));
    std::sort(zs.begin(), zs.end());
    const std::size_t limit = std::max<std::size_t>(2048, (zs.size() + 7) / 8);
    std::size_t i = 0;
    while (i < zs.size()) {
        std::size_t j = std::min(zs.size(), i + limit);
        while (j < zs.size() && zs[j] == zs[j - 1]) ++j;
        const int z0 = zs[i] * 8, z1 = zs[j - 1] * 8 + 8;
        Box piece{glm::ivec3(region.min.x, region.min.y, std::max(region.min.z, z0)),
                  glm::ivec3(region.max.x, region.max.y, std::min(region.max.z, z1))};
        if (!piece.empty()) {
            source.attach(mReader.readRegion(index, leafAligned(piece)));
            vdb::CoordBBox origins(vdb::Coord(INT32_MIN / 2, INT32_MIN / 2, z0), vdb::Coord(INT32_MAX / 2, INT32_MAX / 2, z1 - 1));
            source.forEachActiveLeafVoxel(origins, toCoordBBox(piece), f);
            source.attach(nullptr);
        }
        i = j;
    }
}

void Importer::buildPalette() {
    mMaterials.assign(1, world::Material{});
    switch (mRule) {
        case MaterialRule::Constant: mMaterials.push_back(mOptions.material); break;
        case MaterialRule::Height: {
            auto bands = mOptions.heightMaterials.empty() ? defaultHeightMaterials() : mOptions.heightMaterials;
            mMaterials.insert(mMaterials.end(), bands.begin(), bands.end());
            break;
        }
        case MaterialRule::Ids:
            if (mKind == Kind::VoxIds) {
                const auto& m = mWorldHeader.palette.materials();
                mMaterials.insert(mMaterials.end(), m.begin() + 1, m.end());
            } else {
                std::vector<std::int64_t> values;
                std::unordered_map<std::int64_t, int> seen;
                auto note = [&](std::int64_t v) {
                    if (seen.emplace(v, 0).second) {
                        values.push_back(v);
                        if (values.size() >= world::kMaxMaterials)
                            failImport("{}: grid '{}' holds more than {} distinct ids", mFile, mPlan.grid,
                                       world::kMaxMaterials - 1);
                    }
                };
                if (mStreaming) {
                    streamPass([&](const Box&, const Sample& s) { note(std::int64_t(s.scalar)); },
                               [&](const vdb::Coord& origin, const Sample* samples) {
                                   forLeafVoxels(origin, samples, mSourceBox, [&](const Sample& v) { note(std::int64_t(v.scalar)); });
                               });
                } else {
                    auto topology = makeSource(*mGridHeader);
                    topology->attach(mReader.readTopology(mGridIndex));
                    forEachSolidTile(*topology, [&](const Box&, const Sample& s) { note(std::int64_t(s.scalar)); });
                    topology.reset();
                    scanActive(mGridIndex, mLeaves, mSourceBox, [&](const Sample& v) { note(std::int64_t(v.scalar)); });
                }
                std::sort(values.begin(), values.end());
                for (std::int64_t v : values) {
                    mIdLut[v] = int(mMaterials.size());
                    mMaterials.push_back({fmt::format("id_{}", v), idColour(v), glm::vec3(0.0f), 0.0f});
                }
            }
            break;
        case MaterialRule::Colour: {
            ColourHistogram histogram;
            if (mColourIndex >= 0) {
                // The colour grid's voxels over the imported region (through world space).
                Box region = mSourceBox;
                if (!mSameXform) {
                    vdb::BBoxd world = mShapeXform->indexToWorld(toCoordBBox(mSourceBox));
                    vdb::BBoxd index = mColourXform->worldToIndex(world);
                    region = Box{glm::ivec3(int(std::floor(index.min().x())) - 1, int(std::floor(index.min().y())) - 1,
                                            int(std::floor(index.min().z())) - 1),
                                 glm::ivec3(int(std::ceil(index.max().x())) + 2, int(std::ceil(index.max().y())) + 2,
                                            int(std::ceil(index.max().z())) + 2)};
                }
                scanActive(std::size_t(mColourIndex), mColourLeaves, region,
                           [&](const Sample& s) { histogram.add(s.colour); });
            } else {
                if (mStreaming) {
                    streamPass([&](const Box& b, const Sample& s) { histogram.add(s.colour, volume(b.intersect(mSourceBox))); },
                               [&](const vdb::Coord& origin, const Sample* samples) {
                                   forLeafVoxels(origin, samples, mSourceBox, [&](const Sample& v) { histogram.add(v.colour); });
                               });
                } else {
                    auto topology = makeSource(*mGridHeader);
                    topology->attach(mReader.readTopology(mGridIndex));
                    forEachSolidTile(*topology, [&](const Box& b, const Sample& s) { histogram.add(s.colour, volume(b.intersect(mSourceBox))); });
                    topology.reset();
                    scanActive(mGridIndex, mLeaves, mSourceBox, [&](const Sample& v) { histogram.add(v.colour); });
                }
            }
            std::vector<glm::vec3> palette = quantizeColours(histogram, mOptions.maxColours);
            if (palette.empty()) palette.push_back(glm::vec3(0.7f));
            for (std::size_t i = 0; i < palette.size(); ++i)
                mMaterials.push_back({fmt::format("colour_{:02}", i + 1), palette[i], glm::vec3(0.0f), 0.0f});
            mMapper = std::make_unique<ColourMapper>(palette);
            mReport.colours = int(palette.size());
            break;
        }
        default: break;
    }
}

bool Importer::decideStreaming() const {
    const vdb::GridBase& g = *mGridHeader;
    const bool type = g.isType<vdb::FloatGrid>() || g.isType<vdb::DoubleGrid>() || g.isType<vdb::Int32Grid>() ||
                      g.isType<vdb::Int64Grid>() || g.isType<vdb::Vec3SGrid>() || g.isType<vdb::Vec3DGrid>();
    return mMap.scale == glm::dvec3(1.0) && mColourIndex < 0 && type && mKind != Kind::Mask &&
           mReader.formatVersion() >= vdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION &&
           mReader.grids()[mGridIndex].parent.empty();
}

void Importer::streamPass(const std::function<void(const Box&, const Sample&)>& onTile,
                          const std::function<void(const vdb::Coord&, const Sample*)>& onLeaf) {
    const vdb::GridBase& g = *mGridHeader;
    if (g.isType<vdb::FloatGrid>()) return streamPassTyped<vdb::FloatTree>(onTile, onLeaf);
    if (g.isType<vdb::DoubleGrid>()) return streamPassTyped<vdb::DoubleTree>(onTile, onLeaf);
    if (g.isType<vdb::Int32Grid>()) return streamPassTyped<vdb::Int32Tree>(onTile, onLeaf);
    if (g.isType<vdb::Int64Grid>()) return streamPassTyped<vdb::Int64Tree>(onTile, onLeaf);
    if (g.isType<vdb::Vec3SGrid>()) return streamPassTyped<vdb::Vec3STree>(onTile, onLeaf);
    if (g.isType<vdb::Vec3DGrid>()) return streamPassTyped<vdb::Vec3DTree>(onTile, onLeaf);
    throw vdb::TypeError("grid type cannot be streamed");
}

template <typename TreeT>
void Importer::streamPassTyped(const std::function<void(const Box&, const Sample&)>& onTile,
                               const std::function<void(const vdb::Coord&, const Sample*)>& onLeaf) {
    using Stream = TreeStream<TreeT>;
    using ValueT = typename TreeT::ValueType;
    const Box crop = mOptions.crop ? *mOptions.crop : Box{glm::ivec3(INT32_MIN / 2), glm::ivec3(INT32_MAX / 2)};
    vdb::GridBase::Ptr header = mReader.openTree(mGridIndex);
    const bool half = header->saveFloatAsHalf();
    std::istream& topology = mReader.stream();
    auto tile = [&](const vdb::CoordBBox& box, const ValueT& value, bool active) {
        const Sample s = toSample(value, active);
        if (!solid(s)) return;
        const Box b = toBox(box).intersect(crop);
        if (!b.empty()) onTile(b, s);
    };
    const typename Stream::Root root =
        Stream::walk(topology, mReader.formatVersion(), half, mReader.fileBytes(), nullptr, tile);

    // A second stream over the same file reads the leaf values while the first walks the nodes;
    // it carries the same decoding state (format, compression, grid class and metadata).
    std::ifstream values(mPath, std::ios::in | std::ios::binary);
    if (!values) throw vdb::IoError("cannot reopen " + mFile);
    values.exceptions(std::ios::failbit | std::ios::badbit);
    vdb::io::setVersion(values, vdb::io::getLibraryVersion(topology), vdb::io::getFormatVersion(topology));
    vdb::io::setDataCompression(values, vdb::io::getDataCompression(topology));
    vdb::io::setGridClass(values, vdb::io::getGridClass(topology));
    vdb::io::StreamMetadata::Ptr metadata = vdb::io::getStreamMetadataPtr(topology);
    vdb::io::setStreamMetadataPtr(values, metadata, /*transfer=*/false);
    mReader.seekToBuffers(mGridIndex);
    values.seekg(topology.tellg());

    std::vector<Sample> samples(512);
    Stream::stream(
        topology, &values, mReader.formatVersion(), half, root, tile,
        [&](const vdb::Coord& origin, const typename Stream::LeafMask&) {
            const glm::ivec3 o(origin.x(), origin.y(), origin.z());
            return !Box{o, o + 8}.intersect(mSourceBox).empty();
        },
        [&](const vdb::Coord& origin, const typename Stream::LeafMask& mask, const ValueT* v) {
            for (int i = 0; i < 512; ++i) samples[std::size_t(i)] = toSample(v[i], mask.isOn(vdb::Index(i)));
            onLeaf(origin, samples.data());
        });
}

void Importer::writeTileRegion(BrickGrid& grid, const Box& source, const Sample& s) {
    const Box target = mMap.span(mMap.orient(source), 0.0).intersect(mWorldBox);
    if (target.empty()) return;
    const glm::ivec3 lo = target.min >> 3, hi = (target.max - 1) >> 3;
    for (int cz = lo.z; cz <= hi.z; ++cz)
        for (int cy = lo.y; cy <= hi.y; ++cy)
            for (int cx = lo.x; cx <= hi.x; ++cx) {
                const glm::ivec3 c(cx, cy, cz);
                const Box cellBox{c * 8, c * 8 + 8};
                const Box part = cellBox.intersect(target);
                int material = 0;
                if (part.min == cellBox.min && part.max == cellBox.max && uniformMaterial(s, cellBox, material)) {
                    grid.writeCellUniform(c, mRemap[std::size_t(material)]);
                    mReport.solidVoxels += world::kBrickVoxels;
                    noteWrite(grid);
                    continue;
                }
                world::BrickVoxels voxels = grid.readCell(c);
                for (int z = part.min.z; z < part.max.z; ++z)
                    for (int y = part.min.y; y < part.max.y; ++y)
                        for (int x = part.min.x; x < part.max.x; ++x) {
                            voxels[std::size_t(world::brickVoxelIndex(glm::ivec3(x, y, z) & 7))] =
                                mRemap[std::size_t(materialFor({x, y, z}, s))];
                            mReport.solidVoxels++;
                        }
                grid.writeCell(c, voxels);
                noteWrite(grid);
            }
}

void Importer::writeLeaf(BrickGrid& grid, const vdb::Coord& origin, const Sample* samples) {
    // A leaf lands in one cell when the offset is leaf-aligned, else in up to eight.
    struct Part {
        glm::ivec3 cell;
        world::BrickVoxels voxels;
        std::bitset<512> set;
    };
    std::array<Part, 8> parts;
    int used = 0;
    for (int i = 0; i < 512; ++i) {
        const glm::ivec3 src(origin.x() + (i >> 6), origin.y() + ((i >> 3) & 7), origin.z() + (i & 7));
        if (!mSourceBox.contains(src) || !solid(samples[i])) continue;
        const glm::ivec3 t = mMap.exactTarget(src);
        if (!mWorldBox.contains(t)) continue;
        const glm::ivec3 cell = t >> 3;
        int p = 0;
        while (p < used && parts[std::size_t(p)].cell != cell) ++p;
        if (p == used) {
            parts[std::size_t(used)].cell = cell;
            parts[std::size_t(used)].set.reset();
            ++used;
        }
        const int local = world::brickVoxelIndex(t & 7);
        parts[std::size_t(p)].voxels[std::size_t(local)] = mRemap[std::size_t(materialFor(t, samples[i]))];
        parts[std::size_t(p)].set.set(std::size_t(local));
        mReport.solidVoxels++;
    }
    for (int p = 0; p < used; ++p) {
        Part& part = parts[std::size_t(p)];
        world::BrickVoxels voxels = grid.readCell(part.cell);
        for (std::size_t v = 0; v < 512; ++v)
            if (part.set.test(v)) voxels[v] = part.voxels[v];
        grid.writeCell(part.cell, voxels);
        noteWrite(grid);
    }
}

void Importer::noteWrite(BrickGrid& grid) {
    if (++mWritesSinceClear < 4096) return;
    grid.clearDirty();  // keeps the dirty lists short; an imported world is uploaded whole anyway
    mWritesSinceClear = 0;
}

void Importer::run(world::Scene& scene, bool intoExisting) {
#if defined(__GLIBC__)
    // Planning freed the source topology (thousands of small nodes); hand those pages back to
    // the system before the world is built, or they stay resident as heap fragments. And pin
    // glibc's mmap threshold: OpenVDB's node buffers (128-768 KiB, allocated and freed per node)
    // otherwise raise it, after which they are carved from the heap and linger there.
    malloc_trim(0);
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
    buildPalette();

    // Import materials into the scene's palette: appended in order for a new world (so ids stay
    // exactly as in our own files), merged by name into an existing one.
    mRemap.assign(mMaterials.size(), world::kEmpty);
    for (std::size_t i = 1; i < mMaterials.size(); ++i) {
        std::optional<MaterialId> id;
        if (intoExisting) id = scene.palette.find(mMaterials[i].name);
        if (!id) id = scene.palette.add(mMaterials[i]);
        if (!id) failImport("{}: the palette is full ({} materials)", mFile, world::kMaxMaterials - 1);
        mRemap[i] = *id;
    }
    mReport.materials = mMaterials.size() - 1;

    BrickGrid& grid = scene.grid;
    std::vector<std::uint8_t> marks;
    {
        AllocationBudget::LargeAllocations large;  // checked by the estimate
        if (!intoExisting) grid = BrickGrid(mWorldSize);
        grid.reserveBricks(std::uint32_t(std::min<std::uint64_t>(grid.liveBricks() + mPlan.sampledCells, 0x7FFFFFF0u)));
        if (!mStreaming) marks.assign(std::size_t(volume(Box{glm::ivec3(0), (mWorldSize + 7) / 8})), kCellNone);
    }
    if (mStreaming) {
        streamPass([&](const Box& tile, const Sample& value) { writeTileRegion(grid, tile, value); },
                   [&](const vdb::Coord& origin, const Sample* samples) { writeLeaf(grid, origin, samples); });
        grid.clearDirty();
        mSlabs.clear();
    } else {
        auto topology = makeSource(*mGridHeader);
        topology->attach(mReader.readTopology(mGridIndex));
        markCells(*topology, marks, [&](glm::ivec3 c, int material) {
            grid.writeCellUniform(c, mRemap[std::size_t(material)]);
            mReport.solidVoxels += world::kBrickVoxels;
        });
    }
    grid.clearDirty();

    const glm::ivec3 cells = (mWorldSize + 7) / 8;
    const glm::ivec3 lo = mWorldBox.min >> 3, hi = (mWorldBox.max - 1) >> 3;
    for (const Slab& slab : mSlabs) {
        Box worldPart{glm::ivec3(mWorldBox.min.x, mWorldBox.min.y, std::max(mWorldBox.min.z, slab.cz0 * 8)),
                      glm::ivec3(mWorldBox.max.x, mWorldBox.max.y, std::min(mWorldBox.max.z, slab.cz1 * 8))};
        Box sourcePart = mMap.unorient(mMap.needed(worldPart)).intersect(mSourceBox);
        if (sourcePart.empty()) continue;
        mShape->attach(mReader.readRegion(mGridIndex, leafAligned(sourcePart)));
        if (mColour) {
            Box region = sourcePart;
            if (!mSameXform) {
                vdb::BBoxd index = mColourXform->worldToIndex(mShapeXform->indexToWorld(toCoordBBox(sourcePart)));
                region = Box{glm::ivec3(int(std::floor(index.min().x())), int(std::floor(index.min().y())), int(std::floor(index.min().z()))) - 1,
                             glm::ivec3(int(std::ceil(index.max().x())), int(std::ceil(index.max().y())), int(std::ceil(index.max().z()))) + 2};
            }
            mColour->attach(mReader.readRegion(std::size_t(mColourIndex), leafAligned(region)));
        }
        for (int cz = std::max(slab.cz0, lo.z); cz < std::min(slab.cz1, hi.z + 1); ++cz) {
            for (int cy = lo.y; cy <= hi.y; ++cy) {
                for (int cx = lo.x; cx <= hi.x; ++cx) {
                    const glm::ivec3 c(cx, cy, cz);
                    const std::size_t ci = std::size_t(cx) + std::size_t(cells.x) * (std::size_t(cy) + std::size_t(cells.y) * std::size_t(cz));
                    if (marks[ci] != kCellSample) continue;
                    world::BrickVoxels voxels;
                    if (intoExisting) voxels = grid.readCell(c);
                    else voxels.fill(world::kEmpty);
                    bool any = false;
                    for (int i = 0; i < world::kBrickVoxels; ++i) {
                        const glm::ivec3 t = c * 8 + glm::ivec3(i & 7, (i >> 3) & 7, i >> 6);
                        if (!mWorldBox.contains(t)) continue;
                        Sample s;
                        if (!solidAt(t, s)) continue;
                        voxels[std::size_t(i)] = mRemap[std::size_t(materialFor(t, s))];
                        mReport.solidVoxels++;
                        any = true;
                    }
                    if (any) grid.writeCell(c, voxels);
                }
            }
        }
        // Drop this slab's source values (and the dirty lists) before reading the next.
        mShape->attach(nullptr);
        if (mColour) mColour->attach(nullptr);
        grid.clearDirty();
    }
    mReport.colouredVoxels = mColourError.count;
    mReport.meanColourError = mColourError.mean();
    mReport.maxColourError = mColourError.max;

    if (!intoExisting) {
        scene.name = mOwn ? mWorldHeader.name : mPath.stem().string();
        scene.voxelSize = float(mPlan.voxelSize);
        if (mOwn) {
            scene.cameras = mWorldHeader.cameras;
            scene.sky = mWorldHeader.sky;
        }
        // Into an existing scene the scene file stays the source: `vox capture` reads its [path]
        // from there, and messages name it.
        scene.sourcePath = mFile;
    }
}

template <typename T>
Result<T> runGuarded(const fs::path& path, const VdbImportOptions& options,
                     const std::function<T(std::uint64_t, const AllocationBudget&)>& f) {
    auto bytes = vdbFileBytes(path);
    if (!bytes) return bytes.error();
    AllocationBudget budget(options.memoryBudgetBytes, vdbSingleAllocationLimit(*bytes));
    try {
        return f(*bytes, budget);
    } catch (const ImportFailure& e) {
        return Error{e.message};
    } catch (...) {
        return vdbError(path, &budget);
    }
}

}  // namespace

Result<VdbImportPlan> planVdbImport(const fs::path& path, const VdbImportOptions& options) {
    return runGuarded<VdbImportPlan>(path, options, [&](std::uint64_t, const AllocationBudget&) {
        Importer importer(path, options);
        importer.plan(nullptr);
        return importer.report().plan;
    });
}

Result<world::Scene> importVdb(const fs::path& path, const VdbImportOptions& options, VdbImportReport* report) {
    return runGuarded<world::Scene>(path, options, [&](std::uint64_t, const AllocationBudget& budget) {
        Importer importer(path, options);
        importer.plan(nullptr);
        world::Scene scene;
        importer.run(scene, /*intoExisting=*/false);
        importer.report().peakTrackedBytes = budget.peakBytes();
        if (report) *report = importer.report();
        return scene;
    });
}

Status importVdbInto(world::Scene& scene, const fs::path& path, const VdbImportOptions& options,
                     VdbImportReport* report) {
    auto done = runGuarded<bool>(path, options, [&](std::uint64_t, const AllocationBudget& budget) {
        Importer importer(path, options);
        importer.plan(&scene);
        importer.run(scene, /*intoExisting=*/true);
        importer.report().peakTrackedBytes = budget.peakBytes();
        if (report) *report = importer.report();
        return true;
    });
    if (!done) return done.error();
    return {};
}

std::string formatVdbImportPlan(const VdbImportPlan& p) {
    std::string s;
    s += fmt::format("  grid         '{}' ({}, class {}) as {}\n", p.grid, p.gridType, p.gridClass, p.kind);
    s += fmt::format("  materials    {}\n", p.rule);
    s += fmt::format("  axes         {}; voxel size {:.6g} (source {:.6g} x {:.6g} x {:.6g})\n",
                     p.upZ ? "Z-up turned to Y-up" : "Y-up, as stored", p.voxelSize, p.sourceVoxelSize.x,
                     p.sourceVoxelSize.y, p.sourceVoxelSize.z);
    s += fmt::format("  source box   [{}, {}, {}] .. [{}, {}, {}] (index space, max exclusive)\n", p.sourceBox.min.x,
                     p.sourceBox.min.y, p.sourceBox.min.z, p.sourceBox.max.x, p.sourceBox.max.y, p.sourceBox.max.z);
    s += fmt::format("  world        {} x {} x {} voxels; content at [{}, {}, {}] .. [{}, {}, {}]\n", p.worldSize.x,
                     p.worldSize.y, p.worldSize.z, p.worldBox.min.x, p.worldBox.min.y, p.worldBox.min.z,
                     p.worldBox.max.x, p.worldBox.max.y, p.worldBox.max.z);
    s += fmt::format("  cells        {} read voxel by voxel (at most that many bricks), {} filled whole from tiles\n",
                     p.sampledCells, p.uniformCells);
    s += fmt::format("  memory       about {} ({} world, {} source {}); budget {}\n", mib(p.estimateBytes),
                     mib(p.worldBytes), mib(p.sourceBytes),
                     p.streamed ? std::string("streamed leaf by leaf") : fmt::format("read in {} slab(s)", p.slabs),
                     mib(p.budgetBytes));
    for (const std::string& n : p.notes) s += fmt::format("  note         {}\n", n);
    return s;
}

std::string formatVdbImportReport(const VdbImportReport& r) {
    std::string s = formatVdbImportPlan(r.plan);
    s += fmt::format("  imported     {} solid voxels, {} material(s)\n", r.solidVoxels, r.materials);
    if (r.colours > 0)
        s += fmt::format("  colour error {} voxels mapped to {} colours: mean {:.4f}, max {:.4f} (linear RGB distance)\n",
                         r.colouredVoxels, r.colours, r.meanColourError, r.maxColourError);
    return s;
}

}  // namespace engine::io
