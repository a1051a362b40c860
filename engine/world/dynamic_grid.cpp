#include "world/dynamic_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shared/dynamic_grid.h"
#include "world/solid_voxels.h"

namespace engine::world {

namespace {

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// Voxels gather into per-cell scratch bricks, written once at the end (writeCell builds the
// masks and collapses uniform bricks), rather than voxel by voxel through set().
class ScratchBricks {
public:
    explicit ScratchBricks(const BrickGrid& grid) : mGrid(grid) {
        const glm::ivec3 cells = grid.sizeInCells();
        mSlotOf.assign(std::size_t(cells.x) * cells.y * cells.z, -1);
    }

    // The scratch voxel at `local` (a grid voxel); a new brick starts empty.
    MaterialId& voxel(glm::ivec3 local) {
        std::int32_t& slot = mSlotOf[mGrid.cellIndex(local >> 3)];
        if (slot < 0) {
            slot = std::int32_t(mSlots.size());
            mSlots.emplace_back();
            mSlots.back().fill(kEmpty);
        }
        return mSlots[std::size_t(slot)][std::size_t(brickVoxelIndex(local & 7))];
    }

    // Every scratch brick into its cell of `grid` (the grid they were made for), in cell order.
    void writeInto(BrickGrid& grid) const {
        const glm::ivec3 cells = grid.sizeInCells();
        for (int cz = 0; cz < cells.z; ++cz)
            for (int cy = 0; cy < cells.y; ++cy)
                for (int cx = 0; cx < cells.x; ++cx) {
                    glm::ivec3 c(cx, cy, cz);
                    std::int32_t slot = mSlotOf[grid.cellIndex(c)];
                    if (slot >= 0) grid.writeCell(c, mSlots[std::size_t(slot)]);
                }
    }

private:
    const BrickGrid& mGrid;
    std::vector<std::int32_t> mSlotOf;  // per cell: its scratch brick, or -1
    std::vector<BrickVoxels> mSlots;
};

// One object's model cell `c` (not empty) into the scratch bricks of the grid at `origin`: it
// maps to a small world box whose voxel centres are tested against that cell alone, so every
// world voxel is decided by exactly the model cell its centre falls in. Voxels already taken
// (by an earlier object) stay.
void voxelizeModelCell(const DynamicObject& o, glm::ivec3 c, const glm::dmat4& worldFromModel,
                       const glm::dmat4& modelFromWorld, const DynamicGrid& out,
                       ScratchBricks& scratch, Box& written) {
    const int dim = kBrickDim;
    const Box cellBox = Box{c * dim, c * dim + dim}.intersect(Box{glm::ivec3(0), o.modelSize});
    if (cellBox.empty()) return;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int k = 0; k < 8; ++k) {
        glm::dvec3 corner((k & 1) ? cellBox.max.x : cellBox.min.x,
                          (k & 2) ? cellBox.max.y : cellBox.min.y,
                          (k & 4) ? cellBox.max.z : cellBox.min.z);
        glm::dvec3 w(worldFromModel * glm::dvec4(corner, 1.0));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    // Voxel v's centre is v + 0.5: the voxels whose centres can lie in [lo, hi].
    glm::ivec3 vMin = glm::ivec3(glm::floor(lo - 0.5)), vMax = glm::ivec3(glm::ceil(hi - 0.5));
    for (int z = vMin.z; z <= vMax.z; ++z)
        for (int y = vMin.y; y <= vMax.y; ++y)
            for (int x = vMin.x; x <= vMax.x; ++x) {
                glm::dvec3 m(modelFromWorld * glm::dvec4(x + 0.5, y + 0.5, z + 0.5, 1.0));
                glm::ivec3 mv(glm::floor(m));
                if (!cellBox.contains(mv)) continue;
                MaterialId material = o.model->get(mv);
                if (material == kEmpty) continue;
                glm::ivec3 local = glm::ivec3(x, y, z) - out.origin;
                if (!out.grid.contains(local)) continue;  // rounding at the very edge
                MaterialId& dst = scratch.voxel(local);
                if (dst != kEmpty) continue;
                dst = material;
                written.min = glm::min(written.min, local);
                written.max = glm::max(written.max, local + 1);
            }
}

}  // namespace

DynamicGrid voxelizeObjects(std::span<const DynamicObject> objects) {
    DynamicGrid out;
    if (objects.empty()) return out;

    Box all{glm::ivec3(std::numeric_limits<int>::max()),
            glm::ivec3(std::numeric_limits<int>::min())};
    for (const DynamicObject& o : objects) {
        Box b = o.worldBounds(o.current);
        all.min = glm::min(all.min, b.min);
        all.max = glm::max(all.max, b.max);
        out.instances.push_back({b, o.worldFromModel(o.current), o.worldFromModel(o.previous)});
    }
    const int dim = kBrickDim;
    out.origin =
        glm::ivec3(floorDiv(all.min.x, dim), floorDiv(all.min.y, dim), floorDiv(all.min.z, dim)) *
        dim;
    // Whole 32^3 super cells, as worlds/README.md asks of every world the traversal walks.
    const glm::ivec3 extent = glm::max(all.max - out.origin, glm::ivec3(1));
    out.grid = BrickGrid((extent + 31) / 32 * 32);

    ScratchBricks scratch(out.grid);
    // The coarse occupancy: the cells each object wrote voxels into, object i in box i mod N.
    constexpr std::size_t kBoxes = shared::DYNAMIC_OCCUPANCY_BOXES;
    std::vector<Box> written(std::min(objects.size(), kBoxes),
                             Box{glm::ivec3(std::numeric_limits<int>::max()),
                                 glm::ivec3(std::numeric_limits<int>::min())});
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const DynamicObject& o = objects[i];
        const glm::dmat4 worldFromModel = o.worldFromModel(o.current);
        const glm::dmat4 modelFromWorld = glm::inverse(worldFromModel);
        forEachOccupiedCell(*o.model, [&](glm::ivec3 c) {
            voxelizeModelCell(o, c, worldFromModel, modelFromWorld, out, scratch,
                              written[i % kBoxes]);
        });
    }
    scratch.writeInto(out.grid);
    for (const Box& b : written) {
        if (b.empty()) continue;  // objects that wrote no voxel
        const glm::ivec3 cellMin = b.min / dim * dim, cellMax = (b.max + dim - 1) / dim * dim;
        out.occupancy.push_back(Box{cellMin + out.origin, cellMax + out.origin});
    }
    out.grid.clearDirty();
    return out;
}

bool updateDynamicObjects(std::vector<DynamicObject>& objects, DynamicGrid& grid, double time,
                          double prevTime) {
    bool changed = grid.instances.size() != objects.size();
    for (DynamicObject& o : objects) {
        RigidTransform current = o.poseAt(time), previous = o.poseAt(prevTime);
        changed |= !(current == o.current) || !(previous == o.previous);
        o.current = current;
        o.previous = previous;
    }
    if (!changed) return false;
    std::uint64_t revision = grid.revision;
    grid = voxelizeObjects(objects);
    grid.revision = revision + 1;
    return true;
}

}  // namespace engine::world
