#include "world/world_edits.h"

namespace engine::world {

namespace {

enum class Coverage { None, Partial, Full };

// Visits every cell overlapping `box` (clipped to the world); `editCell` receives the cell and
// its voxel box and returns nothing: it writes through the grid's cell API.
template <typename F>
void forEachCell(const BrickGrid& grid, const Box& box, F&& editCell) {
    Box clipped = box.intersect(grid.bounds());
    if (clipped.empty()) return;
    glm::ivec3 lo = clipped.min >> 3;
    glm::ivec3 hi = (clipped.max - 1) >> 3;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                glm::ivec3 c{x, y, z};
                editCell(c, Box{c * kBrickDim, c * kBrickDim + kBrickDim});
            }
}

// Applies op(p, old) -> new to the voxels of each cell for which inside(p) holds. `coverage`
// classifies a whole cell so fully covered uniform cells never split; it may only answer Full
// when op does not depend on p.
template <typename Cover, typename Inside, typename Op>
void editShape(BrickGrid& grid, const Box& bounds, Cover&& coverage, Inside&& inside, Op&& op) {
    forEachCell(grid, bounds, [&](glm::ivec3 c, const Box& cellBox) {
        Coverage cover = coverage(cellBox);
        if (cover == Coverage::None) return;
        std::uint32_t value = grid.cell(c);
        if (cover == Coverage::Full && !BrickGrid::cellIsBrick(value)) {
            grid.writeCellUniform(c, op(cellBox.min, BrickGrid::cellMaterial(value)));
            return;
        }
        BrickVoxels voxels = grid.readCell(c);
        for (int z = 0; z < kBrickDim; ++z)
            for (int y = 0; y < kBrickDim; ++y)
                for (int x = 0; x < kBrickDim; ++x) {
                    glm::ivec3 p = cellBox.min + glm::ivec3(x, y, z);
                    if (cover == Coverage::Full || inside(p)) {
                        MaterialId& m = voxels[brickVoxelIndex({x, y, z})];
                        m = op(p, m);
                    }
                }
        grid.writeCell(c, voxels);
    });
}

Coverage boxCoverage(const Box& box, const Box& cellBox) {
    Box overlap = box.intersect(cellBox);
    if (overlap.empty()) return Coverage::None;
    return overlap.size() == cellBox.size() ? Coverage::Full : Coverage::Partial;
}

}  // namespace

void fillBox(BrickGrid& grid, const Box& box, MaterialId material) {
    editShape(
        grid, box, [&](const Box& cellBox) { return boxCoverage(box, cellBox); },
        [&](glm::ivec3 p) { return box.contains(p); },
        [&](glm::ivec3, MaterialId) { return material; });
}

Box sphereBounds(glm::vec3 center, float radius) {
    return {glm::ivec3(glm::floor(center - radius)), glm::ivec3(glm::ceil(center + radius)) + 1};
}

namespace {

// Applies `op` to the voxels whose centre lies within `radius` of `center`.
template <typename Op>
void editSphere(BrickGrid& grid, glm::vec3 center, float radius, Op&& op) {
    auto inside = [&](glm::ivec3 p) {
        glm::vec3 d = glm::vec3(p) + 0.5f - center;
        return glm::dot(d, d) <= radius * radius;
    };
    auto coverage = [&](const Box& cellBox) {
        // The sphere is convex: a cell whose 8 corner voxel centres are inside is fully inside.
        int corners = 0;
        for (int i = 0; i < 8; ++i) {
            glm::ivec3 corner{(i & 1) ? cellBox.max.x - 1 : cellBox.min.x,
                              (i & 2) ? cellBox.max.y - 1 : cellBox.min.y,
                              (i & 4) ? cellBox.max.z - 1 : cellBox.min.z};
            corners += inside(corner);
        }
        if (corners == 8) return Coverage::Full;
        // Otherwise the closest point test decides whether the cell can touch the sphere at all.
        glm::vec3 closest = glm::clamp(center, glm::vec3(cellBox.min), glm::vec3(cellBox.max));
        glm::vec3 d = closest - center;
        return glm::dot(d, d) <= (radius + 1.0f) * (radius + 1.0f) ? Coverage::Partial
                                                                   : Coverage::None;
    };
    editShape(grid, sphereBounds(center, radius), coverage, inside, op);
}

}  // namespace

void fillSphere(BrickGrid& grid, glm::vec3 center, float radius, MaterialId material) {
    editSphere(grid, center, radius, [&](glm::ivec3, MaterialId) { return material; });
}

void paintBox(BrickGrid& grid, const Box& box, MaterialId material) {
    editShape(
        grid, box, [&](const Box& cellBox) { return boxCoverage(box, cellBox); },
        [&](glm::ivec3 p) { return box.contains(p); },
        [&](glm::ivec3, MaterialId m) { return m == kEmpty ? kEmpty : material; });
}

void paintSphere(BrickGrid& grid, glm::vec3 center, float radius, MaterialId material) {
    editSphere(grid, center, radius,
               [&](glm::ivec3, MaterialId m) { return m == kEmpty ? kEmpty : material; });
}

void replaceMaterial(BrickGrid& grid, const Box& region, MaterialId from, MaterialId to) {
    editShape(
        grid, region, [&](const Box& cellBox) { return boxCoverage(region, cellBox); },
        [&](glm::ivec3 p) { return region.contains(p); },
        [&](glm::ivec3, MaterialId m) { return m == from ? to : m; });
}

BrickGrid copyRegion(const BrickGrid& grid, const Box& region) {
    BrickGrid clip(glm::max(region.size(), glm::ivec3(1)));
    Box clipped = region.intersect(grid.bounds());
    for (int z = clipped.min.z; z < clipped.max.z; ++z)
        for (int y = clipped.min.y; y < clipped.max.y; ++y)
            for (int x = clipped.min.x; x < clipped.max.x; ++x) {
                MaterialId m = grid.get({x, y, z});
                if (m != kEmpty) clip.set(glm::ivec3(x, y, z) - region.min, m);
            }
    clip.clearDirty();
    return clip;
}

void pasteRegion(BrickGrid& grid, const BrickGrid& clip, glm::ivec3 at, bool skipEmpty) {
    Box target{at, at + clip.sizeInVoxels()};
    editShape(
        grid, target,
        [&](const Box& cellBox) {
            return boxCoverage(target, cellBox) == Coverage::None ? Coverage::None
                                                                  : Coverage::Partial;
        },
        [&](glm::ivec3 p) { return target.contains(p); },
        [&](glm::ivec3 p, MaterialId old) {
            MaterialId m = clip.get(p - at);
            return (skipEmpty && m == kEmpty) ? old : m;
        });
}

}  // namespace engine::world
