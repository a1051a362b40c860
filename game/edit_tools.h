// Edit tools: what a click does to the world. The pick is a CPU ray from the crosshair
// (world/ray_traversal.h, the reference the GPU traversal agrees with), so the voxel under the
// crosshair is the voxel edited. Tools: place (on the face hit), remove, paint; brushes: one
// voxel, a box dragged between two corners (press at one, release at the other), a sphere of
// a given radius. An eyedropper takes the material under the crosshair.
//
// A click becomes an EditOp, a complete description of the edit: the sandbox applies it
// through the undo history and can log it (tests replay the log on the CPU).
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "world/brick_grid.h"
#include "world/material.h"

namespace game {

enum class Tool { Place, Remove, Paint };
enum class Brush { Voxel, Box, Sphere };
const char* toolName(Tool tool);
const char* brushName(Brush brush);

struct Pick {
    bool hit = false;
    // False when the view ray was not finite (a NaN or infinite camera): nothing is picked, so no
    // click can edit voxel (0, 0, 0) by accident.
    bool validRay = true;
    glm::ivec3 voxel{0};   // the voxel hit
    glm::ivec3 normal{0};  // outward normal of the face the ray entered through
    engine::world::MaterialId material = engine::world::kEmpty;
    float distance = 0.0f;
    glm::ivec3 adjacent() const { return voxel + normal; }
};

inline constexpr float kPickDistance = 1024.0f;  // voxels
Pick pick(const engine::world::BrickGrid& grid, glm::vec3 origin, glm::vec3 direction,
          float maxDistance = kPickDistance);

// Why aiming at `target` cannot edit: "aiming at the sky", or the ray is not finite. Empty when
// it hits a voxel.
std::string missReason(const Pick& target);

struct EditOp {
    Tool tool = Tool::Place;
    Brush brush = Brush::Voxel;
    engine::world::Box box;  // Voxel and Box brushes
    glm::vec3 center{0.0f};  // Sphere brush, in voxel units
    float radius = 0.0f;
    engine::world::MaterialId material = engine::world::kEmpty;

    // The voxels the edit may change (what the undo history snapshots).
    engine::world::Box region() const;
    std::string describe(const engine::world::Palette& palette) const;
};

// Applies the edit (no undo: see UndoHistory::record).
void applyEdit(engine::world::BrickGrid& grid, const EditOp& op);
// Why an edit that changed no voxel changed nothing: outside the world, already that material,
// nothing there to remove or paint.
std::string unchangedReason(const engine::world::BrickGrid& grid, const EditOp& op,
                            const engine::world::Palette& palette);

class EditTools {
public:
    Tool tool = Tool::Place;
    Brush brush = Brush::Voxel;
    engine::world::MaterialId material = 1;
    float radius = 3.0f;

    // The apply button went down / came up while aiming at `target`. Returns the edit to apply:
    // one voxel and sphere edits on press, a box on release (anchored at the press). A box
    // released over the sky (or with an invalid ray) is cancelled: no edit, and missReason says
    // why.
    std::optional<EditOp> press(const Pick& target);
    std::optional<EditOp> release(const Pick& target);
    void cancelDrag() { mAnchor.reset(); }
    bool dragging() const { return mAnchor.has_value(); }
    // The box the next edit would touch, for the HUD's outline.
    std::optional<engine::world::Box> preview(const Pick& target) const;
    // Takes the material under the crosshair; false when aiming at nothing.
    bool eyedrop(const Pick& target);

private:
    // Place works on the empty voxel in front of the face hit; remove and paint on the voxel hit.
    glm::ivec3 targetVoxel(const Pick& p) const {
        return tool == Tool::Place ? p.adjacent() : p.voxel;
    }
    EditOp makeOp() const;

    std::optional<glm::ivec3> mAnchor;
};

}  // namespace game
