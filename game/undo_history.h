// Undo/redo for world edits and dynamic-object changes. A step stores, for each top-grid cell the
// edit changed, that cell's other state: a material for a uniform (or empty) cell, or a copy of its
// 8^3 brick. Undo and redo swap the stored state with the world's, so one copy serves both
// directions and the history costs what the edits touched, never a copy of the world. An object
// step (game/object_tools.h) stores the one object it changed the same way: its other state, or its
// absence, swapped with the scene's list. The object's model is shared, not copied
// (world/dynamic_object.h): a step counts the model's memory only while it alone keeps the model
// alive, that is while the scene's object at its index does not hold the same model (a deleted
// object, a placement undone); a move or a key costs the object's path, not its model.
//
// Memory is bounded: after each edit the oldest steps are dropped until the history fits in
// maxBytes; an edit that alone exceeds the budget is applied but cannot be undone (reported),
// and ends the history: the steps before it could not be undone past it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "world/brick_grid.h"
#include "world/dynamic_object.h"

namespace game {

struct UndoStats {
    std::size_t bytes = 0;         // memory held by the history
    std::size_t maxBytes = 0;      // the budget
    std::size_t undoSteps = 0;     // steps that can be undone
    std::size_t redoSteps = 0;     // steps that can be redone
    std::size_t droppedSteps = 0;  // oldest steps dropped to stay within budget, since the start
};

struct EditRecord {
    std::size_t changedCells = 0;  // cells whose contents the edit changed (the bricks to upload)
    bool undoable = false;         // false if nothing changed or the step exceeded the budget
};

class UndoHistory {
public:
    explicit UndoHistory(std::size_t maxBytes) : mMaxBytes(maxBytes) {}

    // Runs `edit` on `grid` and records the cells within `region` that it changed as one step.
    // `edit` must not change anything outside `region`. Clears the redo steps if it changed
    // something.
    EditRecord record(engine::world::BrickGrid& grid, const engine::world::Box& region,
                      std::string label,
                      const std::function<void(engine::world::BrickGrid&)>& edit);

    // Records a change the caller has just made to objects[index] as one step: `before` is the
    // object before it (nullopt: the change placed it), `existsNow` false when it deleted it.
    // `objects` is the scene's list after the change. Clears the redo steps. Returns false when
    // the step exceeded the budget (not undoable).
    bool recordObject(const std::vector<engine::world::DynamicObject>& objects, std::size_t index,
                      std::optional<engine::world::DynamicObject> before, bool existsNow,
                      std::string label);

    // Each returns the step's label, or an empty string when there is nothing to undo/redo.
    std::string undo(engine::world::BrickGrid& grid,
                     std::vector<engine::world::DynamicObject>& objects);
    std::string redo(engine::world::BrickGrid& grid,
                     std::vector<engine::world::DynamicObject>& objects);
    // For histories of grid edits only (an object step there is a logic error).
    std::string undo(engine::world::BrickGrid& grid);
    std::string redo(engine::world::BrickGrid& grid);

    // The regions (world/region.h) the grid steps touch, sorted: a streamed world keeps them in
    // memory (game/streamed_world.h), so an undo never writes into a region that left.
    std::vector<engine::world::RegionKey> regions() const;

    bool canUndo() const { return mCursor > 0; }
    bool canRedo() const { return mCursor < mSteps.size(); }
    UndoStats stats() const;
    void setMaxBytes(std::size_t maxBytes);
    void clear();

private:
    // One cell's stored state: uniform material, or brick `brick` in Step::bricks.
    struct CellState {
        glm::ivec3 cell{0};
        std::uint32_t brick = kNoBrick;
        engine::world::MaterialId material = engine::world::kEmpty;
    };
    static constexpr std::uint32_t kNoBrick = UINT32_MAX;
    struct Step {
        std::string label;
        std::vector<CellState> cells;
        std::vector<engine::world::BrickVoxels> bricks;
        // An object step: object `objectIndex`'s other state (nullopt: absent there), and
        // whether the scene's list holds it now.
        bool isObject = false;
        std::size_t objectIndex = 0;
        bool objectInScene = false;
        std::optional<engine::world::DynamicObject> objectOther;
        bool holdsModel = false;  // objectOther's model is not the scene's object's: counted here
        std::size_t bytes() const;
    };

    static void capture(const engine::world::BrickGrid& grid, glm::ivec3 cell, Step& step,
                        CellState& state);
    // Writes the step's states into the grid and keeps the grid's previous states in their place.
    static void swap(engine::world::BrickGrid& grid, Step& step);
    static void swapObject(std::vector<engine::world::DynamicObject>& objects, Step& step);
    static bool holdsModelAlone(const Step& step,
                                const std::vector<engine::world::DynamicObject>& objects);
    void push(Step step);
    void enforceBudget();

    std::size_t mMaxBytes;
    std::deque<Step> mSteps;
    std::size_t mCursor = 0;  // steps [0, mCursor) are undoable, [mCursor, size) redoable
    std::size_t mBytes = 0;
    std::size_t mDropped = 0;
};

}  // namespace game
