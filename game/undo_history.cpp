#include "game/undo_history.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace game {

namespace world = engine::world;

namespace {

// What an object holds of its own: everything but the shared model.
std::size_t objectBytes(const world::DynamicObject& o) {
    std::size_t bytes = sizeof(o) + o.name.capacity() +
                        o.path.keys().capacity() * sizeof(world::ObjectKey) +
                        o.generators.capacity() * sizeof(world::GeneratorRecord);
    for (const world::GeneratorRecord& g : o.generators) bytes += g.type.capacity();
    return bytes;
}

// The heap a model's grid takes: its brick pool in whole pages, however few bricks are live.
std::size_t modelBytes(const world::BrickGrid& model) {
    const world::GridMemory m = model.memory();
    return m.topGridBytes + m.superGridBytes + m.bookkeepingBytes +
           world::BrickGrid::poolBytesFor(model.brickCapacity());
}

}  // namespace

std::size_t UndoHistory::Step::bytes() const {
    std::size_t object = 0;
    if (objectOther)
        object = objectBytes(*objectOther) + (holdsModel ? modelBytes(*objectOther->model) : 0);
    return sizeof(Step) + label.capacity() + cells.capacity() * sizeof(CellState) +
           bricks.capacity() * sizeof(world::BrickVoxels) + object;
}

bool UndoHistory::holdsModelAlone(const Step& step,
                                  const std::vector<world::DynamicObject>& objects) {
    if (!step.objectOther) return false;
    const bool shared = step.objectInScene && step.objectIndex < objects.size() &&
                        objects[step.objectIndex].model == step.objectOther->model;
    return !shared;
}

void UndoHistory::capture(const world::BrickGrid& grid, glm::ivec3 cell, Step& step,
                          CellState& state) {
    std::uint32_t value = grid.cell(cell);
    state.cell = cell;
    if (world::BrickGrid::cellIsBrick(value)) {
        state.brick = static_cast<std::uint32_t>(step.bricks.size());
        step.bricks.push_back(grid.brickVoxels(world::BrickGrid::cellBrick(value)));
        state.material = world::kEmpty;
    } else {
        state.brick = kNoBrick;
        state.material = world::BrickGrid::cellMaterial(value);
    }
}

EditRecord UndoHistory::record(world::BrickGrid& grid, const world::Box& region, std::string label,
                               const std::function<void(world::BrickGrid&)>& edit) {
    EditRecord result;
    world::Box clipped = region.intersect(grid.bounds());
    if (clipped.empty()) return result;

    // Snapshot every cell the region overlaps; keep only those the edit changed.
    Step before;
    before.label = std::move(label);
    glm::ivec3 lo = clipped.min >> 3, hi = (clipped.max - 1) >> 3;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                CellState s;
                capture(grid, {x, y, z}, before, s);
                before.cells.push_back(s);
            }
    edit(grid);

    Step step;
    step.label = std::move(before.label);
    for (const CellState& s : before.cells) {
        std::uint32_t now = grid.cell(s.cell);
        bool changed;
        if (s.brick == kNoBrick) {
            changed = world::BrickGrid::cellIsBrick(now) ||
                      world::BrickGrid::cellMaterial(now) != s.material;
        } else {
            changed = !world::BrickGrid::cellIsBrick(now) ||
                      grid.brickVoxels(world::BrickGrid::cellBrick(now)) != before.bricks[s.brick];
        }
        if (!changed) continue;
        CellState kept = s;
        if (s.brick != kNoBrick) {
            kept.brick = static_cast<std::uint32_t>(step.bricks.size());
            step.bricks.push_back(before.bricks[s.brick]);
        }
        step.cells.push_back(kept);
    }
    result.changedCells = step.cells.size();
    if (step.cells.empty()) return result;
    step.cells.shrink_to_fit();
    step.bricks.shrink_to_fit();

    result.undoable = step.bytes() <= mMaxBytes;
    push(std::move(step));
    return result;
}

void UndoHistory::push(Step step) {
    // A new edit forks history: the redo steps are gone.
    while (mSteps.size() > mCursor) {
        mBytes -= mSteps.back().bytes();
        mSteps.pop_back();
    }
    std::size_t bytes = step.bytes();
    if (bytes > mMaxBytes) {
        // Too large to keep: applied, not undoable. The steps before it go too: they no longer
        // lead back from the world as it is now (an object step names its object by its place in
        // the list), and they would keep alive what they hold (a deleted object's model).
        mDropped += mSteps.size() + 1;
        clear();
        return;
    }
    mSteps.push_back(std::move(step));
    mBytes += bytes;
    mCursor = mSteps.size();
    enforceBudget();
}

bool UndoHistory::recordObject(const std::vector<world::DynamicObject>& objects, std::size_t index,
                               std::optional<world::DynamicObject> before, bool existsNow,
                               std::string label) {
    Step step;
    step.label = std::move(label);
    step.isObject = true;
    step.objectIndex = index;
    step.objectInScene = existsNow;
    step.objectOther = std::move(before);
    step.holdsModel = holdsModelAlone(step, objects);
    bool undoable = step.bytes() <= mMaxBytes;
    push(std::move(step));
    return undoable;
}

void UndoHistory::swapObject(std::vector<world::DynamicObject>& objects, Step& step) {
    const std::size_t i = step.objectIndex;
    if (i > objects.size() || (step.objectInScene && i >= objects.size()))
        throw std::logic_error("undo: an object step does not match the scene's objects");
    std::optional<world::DynamicObject> now;
    if (step.objectInScene) {
        now = std::move(objects[i]);
        objects.erase(objects.begin() + std::ptrdiff_t(i));
    }
    if (step.objectOther)
        objects.insert(objects.begin() + std::ptrdiff_t(i), std::move(*step.objectOther));
    step.objectInScene = step.objectOther.has_value();
    step.objectOther = std::move(now);
    step.holdsModel = holdsModelAlone(step, objects);
}

void UndoHistory::swap(world::BrickGrid& grid, Step& step) {
    std::vector<world::BrickVoxels> bricks;
    std::vector<CellState> cells;
    cells.reserve(step.cells.size());
    for (const CellState& s : step.cells) {
        CellState current;
        std::uint32_t value = grid.cell(s.cell);
        current.cell = s.cell;
        if (world::BrickGrid::cellIsBrick(value)) {
            current.brick = static_cast<std::uint32_t>(bricks.size());
            bricks.push_back(grid.brickVoxels(world::BrickGrid::cellBrick(value)));
        } else {
            current.material = world::BrickGrid::cellMaterial(value);
        }
        if (s.brick == kNoBrick) {
            grid.writeCellUniform(s.cell, s.material);
        } else {
            grid.writeCell(s.cell, step.bricks[s.brick]);
        }
        cells.push_back(current);
    }
    step.cells = std::move(cells);
    step.bricks = std::move(bricks);
    step.cells.shrink_to_fit();
    step.bricks.shrink_to_fit();
}

std::string UndoHistory::undo(world::BrickGrid& grid) {
    std::vector<world::DynamicObject> none;
    return undo(grid, none);
}

std::string UndoHistory::redo(world::BrickGrid& grid) {
    std::vector<world::DynamicObject> none;
    return redo(grid, none);
}

std::string UndoHistory::undo(world::BrickGrid& grid, std::vector<world::DynamicObject>& objects) {
    if (!canUndo()) return {};
    Step& step = mSteps[--mCursor];
    mBytes -= step.bytes();
    if (step.isObject)
        swapObject(objects, step);
    else
        swap(grid, step);
    mBytes += step.bytes();
    std::string label = step.label;
    enforceBudget();
    return label;
}

std::string UndoHistory::redo(world::BrickGrid& grid, std::vector<world::DynamicObject>& objects) {
    if (!canRedo()) return {};
    Step& step = mSteps[mCursor++];
    mBytes -= step.bytes();
    if (step.isObject)
        swapObject(objects, step);
    else
        swap(grid, step);
    mBytes += step.bytes();
    std::string label = step.label;
    enforceBudget();
    return label;
}

void UndoHistory::enforceBudget() {
    // A swap can grow a step (a uniform cell's state becomes a brick), so this runs after undo
    // and redo too. Drop the oldest undo steps first, then the furthest redo steps.
    while (mBytes > mMaxBytes && !mSteps.empty()) {
        if (mCursor > 0) {
            mBytes -= mSteps.front().bytes();
            mSteps.pop_front();
            --mCursor;
        } else {
            mBytes -= mSteps.back().bytes();
            mSteps.pop_back();
        }
        ++mDropped;
    }
}

UndoStats UndoHistory::stats() const {
    return {mBytes, mMaxBytes, mCursor, mSteps.size() - mCursor, mDropped};
}

void UndoHistory::setMaxBytes(std::size_t maxBytes) {
    mMaxBytes = maxBytes;
    enforceBudget();
}

void UndoHistory::clear() {
    mSteps.clear();
    mCursor = 0;
    mBytes = 0;
}

std::vector<engine::world::RegionKey> UndoHistory::regions() const {
    std::vector<engine::world::RegionKey> keys;
    for (const Step& step : mSteps)
        for (const CellState& c : step.cells) keys.push_back(engine::world::regionOfCell(c.cell));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

}  // namespace game
