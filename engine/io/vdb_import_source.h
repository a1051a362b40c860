// Source grids for OpenVDB import (io/vdb_import.h): a type-erased view of one OpenVDB grid,
// just the parts the importer reads, so the import is written once instead of once per value
// type; and the kinds of grid it imports. Internal to engine/io (it exposes OpenVDB types).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <openvdb/openvdb.h>
#include <optional>
#include <type_traits>

#include "core/error.h"

namespace engine::io::vdb_import {

// How a grid's values become solid voxels (io/vdb_import.h lists the rules).
enum class Kind { VoxIds, LevelSet, Fog, Ids, Mask, Colour };

const char* kindName(Kind kind);
// None for value types the importer cannot read.
std::optional<Kind> kindOf(const openvdb::GridBase& grid);
bool isColourType(const openvdb::GridBase& grid);

// One voxel or tile value, whatever the grid's type: scalars (bool, ints, floats) in `scalar`,
// vec3 in `colour`.
struct Sample {
    double scalar = 0.0;
    glm::vec3 colour{0.0f};
    bool active = false;
};

template <typename T>
Sample toSample(const T& value, bool active) {
    Sample s;
    s.active = active;
    if constexpr (std::is_same_v<T, bool>) {
        s.scalar = value ? 1.0 : 0.0;
    } else if constexpr (std::is_arithmetic_v<T>) {
        s.scalar = double(value);
    } else {
        s.colour = glm::vec3(float(value.x()), float(value.y()), float(value.z()));
    }
    return s;
}

class SourceGrid {
public:
    using TileFn = std::function<Status(const openvdb::CoordBBox&, const Sample&)>;
    using VoxelFn = std::function<Status(const Sample&)>;

    virtual ~SourceGrid() = default;
    // As read by VdbReader (of the type makeSource() was given); nullptr releases it.
    virtual void attach(openvdb::GridBase::Ptr grid) = 0;
    virtual openvdb::GridBase::ConstPtr base() const = 0;
    virtual Sample at(const openvdb::Coord& ijk) const = 0;  // leaf values must be loaded
    virtual double trilinear(
        const openvdb::Vec3d& ijk) const = 0;  // index space, voxel centres at integers
    // Leaves (node box, active voxel count) and tiles above leaf level (box, value). The
    // walks stop at the first callback that fails and return its error.
    virtual void forEachLeaf(
        const std::function<void(const openvdb::CoordBBox&, std::uint64_t)>& f) const = 0;
    virtual Status forEachTile(const TileFn& f) const = 0;
    // Active voxels inside `box` of the loaded leaves whose origin lies in `origins`.
    virtual Status forEachActiveLeafVoxel(const openvdb::CoordBBox& origins,
                                          const openvdb::CoordBBox& box,
                                          const VoxelFn& f) const = 0;
};

// A view for grids of `grid`'s type, or null when the importer cannot read that type.
std::unique_ptr<SourceGrid> makeSource(const openvdb::GridBase& grid);

}  // namespace engine::io::vdb_import
