#include "game/edit_tools.h"

#include <cmath>
#include <fmt/format.h>

#include "world/ray_traversal.h"
#include "world/world_edits.h"

namespace game {

namespace world = engine::world;

const char* toolName(Tool tool) {
    switch (tool) {
        case Tool::Place:
            return "place";
        case Tool::Remove:
            return "remove";
        case Tool::Paint:
            return "paint";
    }
    return "?";
}

const char* brushName(Brush brush) {
    switch (brush) {
        case Brush::Voxel:
            return "voxel";
        case Brush::Box:
            return "box";
        case Brush::Sphere:
            return "sphere";
    }
    return "?";
}

Pick pick(const world::BrickGrid& grid, glm::vec3 origin, glm::vec3 direction, float maxDistance) {
    Pick p;
    // A NaN ray would traverse to voxel (0, 0, 0) and "hit" it: refuse it instead.
    float lengths = glm::dot(origin, origin) + glm::dot(direction, direction) + maxDistance;
    if (!std::isfinite(lengths) || glm::dot(direction, direction) == 0.0f) {
        p.validRay = false;
        return p;
    }
    world::Ray ray{origin, glm::normalize(direction), maxDistance};
    world::RayHit hit = world::traceRay(grid, ray);
    if (!hit.hit) return p;
    p.hit = true;
    p.voxel = hit.voxel;
    p.material = hit.material;
    p.distance = hit.t;
    if (hit.face < 6) {
        p.normal = world::faceNormal(hit.face);
    } else {
        // The camera is inside a solid voxel: "in front" is back along the ray's main axis.
        glm::vec3 a = glm::abs(ray.direction);
        int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
        p.normal[axis] = ray.direction[axis] > 0.0f ? -1 : 1;
    }
    return p;
}

std::string missReason(const Pick& target) {
    if (!target.validRay)
        return "the view ray is not finite (camera position or direction is NaN or infinite)";
    if (!target.hit)
        return fmt::format("aiming at the sky (nothing within {:.0f} voxels)", kPickDistance);
    return {};
}

world::Box EditOp::region() const {
    if (brush == Brush::Sphere) return world::sphereBounds(center, radius);
    return box;
}

std::string EditOp::describe(const world::Palette& palette) const {
    std::string what =
        material < palette.size() ? palette[material].name : fmt::format("#{}", material);
    if (brush == Brush::Sphere)
        return fmt::format("{} sphere r{:.1f} at ({:.1f}, {:.1f}, {:.1f}){}", toolName(tool),
                           radius, center.x, center.y, center.z,
                           tool == Tool::Remove ? "" : " " + what);
    glm::ivec3 s = box.size();
    if (s == glm::ivec3(1))
        return fmt::format("{} voxel ({}, {}, {}){}", toolName(tool), box.min.x, box.min.y,
                           box.min.z, tool == Tool::Remove ? "" : " " + what);
    return fmt::format("{} box {}x{}x{} at ({}, {}, {}){}", toolName(tool), s.x, s.y, s.z,
                       box.min.x, box.min.y, box.min.z, tool == Tool::Remove ? "" : " " + what);
}

void applyEdit(world::BrickGrid& grid, const EditOp& op) {
    if (op.brush == Brush::Sphere) {
        switch (op.tool) {
            case Tool::Place:
                world::fillSphere(grid, op.center, op.radius, op.material);
                break;
            case Tool::Remove:
                world::fillSphere(grid, op.center, op.radius, world::kEmpty);
                break;
            case Tool::Paint:
                world::paintSphere(grid, op.center, op.radius, op.material);
                break;
        }
        return;
    }
    switch (op.tool) {
        case Tool::Place:
            world::fillBox(grid, op.box, op.material);
            break;
        case Tool::Remove:
            world::fillBox(grid, op.box, world::kEmpty);
            break;
        case Tool::Paint:
            world::paintBox(grid, op.box, op.material);
            break;
    }
}

std::string unchangedReason(const world::BrickGrid& grid, const EditOp& op,
                            const world::Palette& palette) {
    world::Box r = op.region();
    world::Box b = grid.bounds();
    world::Box inside{glm::max(r.min, b.min), glm::min(r.max, b.max)};
    glm::ivec3 s = b.size();
    if (inside.empty())
        return fmt::format("it lies outside the world (0..{}, 0..{}, 0..{})", s.x, s.y, s.z);
    std::string what =
        op.material < palette.size() ? palette[op.material].name : fmt::format("#{}", op.material);
    switch (op.tool) {
        case Tool::Place:
            return fmt::format("every voxel there is already {}", what);
        case Tool::Remove:
            return "there is nothing to remove there";
        case Tool::Paint:
            return fmt::format("no solid voxel there to paint, or all are already {}", what);
    }
    return {};
}

EditOp EditTools::makeOp() const {
    EditOp op;
    op.tool = tool;
    op.brush = brush;
    op.material = tool == Tool::Remove ? world::kEmpty : material;
    op.radius = radius;
    return op;
}

std::optional<EditOp> EditTools::press(const Pick& target) {
    mAnchor.reset();
    if (!target.hit) return std::nullopt;
    glm::ivec3 v = targetVoxel(target);
    EditOp op = makeOp();
    switch (brush) {
        case Brush::Voxel:
            op.box = {v, v + 1};
            return op;
        case Brush::Sphere:
            op.center = glm::vec3(v) + 0.5f;
            return op;
        case Brush::Box:
            mAnchor = v;
            return std::nullopt;
    }
    return std::nullopt;
}

std::optional<EditOp> EditTools::release(const Pick& target) {
    if (!mAnchor) return std::nullopt;
    glm::ivec3 a = *mAnchor;
    mAnchor.reset();
    // Released over the sky: no second corner, so no box (the sandbox says why).
    if (!target.hit) return std::nullopt;
    glm::ivec3 b = targetVoxel(target);
    EditOp op = makeOp();
    op.box = {glm::min(a, b), glm::max(a, b) + 1};
    return op;
}

std::optional<world::Box> EditTools::preview(const Pick& target) const {
    if (mAnchor) {
        glm::ivec3 b = target.hit ? targetVoxel(target) : *mAnchor;
        return world::Box{glm::min(*mAnchor, b), glm::max(*mAnchor, b) + 1};
    }
    if (!target.hit) return std::nullopt;
    glm::ivec3 v = targetVoxel(target);
    if (brush == Brush::Sphere) return world::sphereBounds(glm::vec3(v) + 0.5f, radius);
    return world::Box{v, v + 1};
}

bool EditTools::eyedrop(const Pick& target) {
    if (!target.hit || target.material == world::kEmpty) return false;
    material = target.material;
    return true;
}

}  // namespace game
