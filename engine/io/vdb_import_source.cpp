// Source grids for OpenVDB import: SourceGrid for each value type the importer reads
// (io/vdb_import_source.h).
#include "io/vdb_import_source.h"

#include <openvdb/tools/Interpolation.h>

#include "core/check.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

namespace {

template <typename GridT>
class TypedSource final : public SourceGrid {
public:
    using ValueT = typename GridT::ValueType;

    void attach(vdb::GridBase::Ptr grid) override {
        mAccessor.reset();
        mGrid.reset();
        if (!grid) return;
        mGrid = vdb::GridBase::grid<GridT>(grid);
        // The reader gives every read of one grid the type its descriptor names, and instances
        // the type of the grid they share (io/vdb_reader.cpp), so this is a bug, not a bad file.
        CHECK_MSG(mGrid, "grid '%s' changed type between reads", grid->getName().c_str());
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
    void forEachLeaf(
        const std::function<void(const vdb::CoordBBox&, std::uint64_t)>& f) const override {
        for (auto it = mGrid->tree().cbeginLeaf(); it; ++it)
            f(it->getNodeBoundingBox(), it->onVoxelCount());
    }
    Status forEachTile(const TileFn& f) const override {
        auto it = mGrid->tree().cbeginValueAll();
        it.setMaxDepth(it.getLeafDepth() - 1);  // tiles only: never look at leaf values
        for (; it; ++it) {
            vdb::CoordBBox box;
            it.getBoundingBox(box);
            if (Status s = f(box, toSample(*it, it.isValueOn())); !s) return s;
        }
        return {};
    }
    Status forEachActiveLeafVoxel(const vdb::CoordBBox& origins, const vdb::CoordBBox& box,
                                  const VoxelFn& f) const override {
        for (auto leaf = mGrid->tree().cbeginLeaf(); leaf; ++leaf) {
            if (!origins.isInside(leaf->origin())) continue;
            for (auto v = leaf->cbeginValueOn(); v; ++v)
                if (box.isInside(v.getCoord()))
                    if (Status s = f(toSample(*v, true)); !s) return s;
        }
        return {};
    }

private:
    typename GridT::Ptr mGrid;
    std::unique_ptr<typename GridT::ConstAccessor> mAccessor;
};

}  // namespace

const char* kindName(Kind kind) {
    switch (kind) {
        case Kind::VoxIds:
            return "voxengine world";
        case Kind::LevelSet:
            return "level set";
        case Kind::Fog:
            return "fog volume";
        case Kind::Ids:
            return "integer ids";
        case Kind::Mask:
            return "mask";
        case Kind::Colour:
            return "colour";
    }
    return "?";
}

bool isColourType(const vdb::GridBase& g) {
    return g.isType<vdb::Vec3SGrid>() || g.isType<vdb::Vec3DGrid>();
}

std::optional<Kind> kindOf(const vdb::GridBase& g) {
    if (g.isType<vdb::FloatGrid>() || g.isType<vdb::DoubleGrid>())
        return g.getGridClass() == vdb::GRID_LEVEL_SET ? Kind::LevelSet : Kind::Fog;
    if (g.isType<vdb::Int32Grid>() || g.isType<vdb::Int64Grid>()) return Kind::Ids;
    if (g.isType<vdb::BoolGrid>() || g.isType<vdb::MaskGrid>()) return Kind::Mask;
    if (isColourType(g)) return Kind::Colour;
    return std::nullopt;
}

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

}  // namespace engine::io::vdb_import
