// Undo/redo restores the world exactly, costs what the edits touched, and stays within its
// memory budget.
#include "game/undo_history.h"

#include <gtest/gtest.h>

#include "core/hash.h"
#include "game/edit_tools.h"
#include "world/random_worlds.h"

using namespace engine::world;
using game::EditOp;
using game::UndoHistory;

namespace {

constexpr std::size_t kMiB = 1u << 20;

// A random edit of every kind the tools make: voxels, boxes, spheres; place, remove, paint.
EditOp randomEdit(engine::Rng& rng, glm::ivec3 size) {
    EditOp op;
    op.tool = static_cast<game::Tool>(rng.uniformInt(0, 2));
    op.brush = static_cast<game::Brush>(rng.uniformInt(0, 2));
    op.material = op.tool == game::Tool::Remove ? kEmpty : MaterialId(rng.uniformInt(1, 6));
    glm::ivec3 a(rng.uniformInt(0, size.x - 1), rng.uniformInt(0, size.y - 1),
                 rng.uniformInt(0, size.z - 1));
    if (op.brush == game::Brush::Voxel) {
        op.box = {a, a + 1};
    } else if (op.brush == game::Brush::Box) {
        glm::ivec3 e(rng.uniformInt(1, 20), rng.uniformInt(1, 20), rng.uniformInt(1, 20));
        op.box = {a, glm::min(a + e, size)};
    } else {
        op.center = glm::vec3(a) + 0.5f;
        op.radius = rng.uniform(0.5f, 9.0f);
    }
    return op;
}

void expectSameCells(const BrickGrid& a, const BrickGrid& b) {
    // operator== compares voxels and cell encodings (homogeneous vs brick); pool slots may differ.
    ASSERT_TRUE(a == b);
    EXPECT_EQ(a.liveBricks(), b.liveBricks());
    EXPECT_EQ(a.homogeneousCells(), b.homogeneousCells());
}

}  // namespace

TEST(UndoHistory, ThousandRandomEditsUndoToTheStartBitForBitAndRedoToTheEnd) {
    BrickGrid grid = testing_worlds::makeWorld(testing_worlds::Kind::Mixed, 7, {80, 48, 72});
    const BrickGrid start = grid;
    UndoHistory history(512 * kMiB);
    engine::Rng rng(2024);
    // 1000 edits that change something (random paint in the air changes nothing, and is
    // not an undo step).
    std::size_t changed = 0, tried = 0;
    while (changed < 1000) {
        EditOp op = randomEdit(rng, grid.sizeInVoxels());
        game::EditRecord r = history.record(grid, op.region(), "edit",
                                            [&](BrickGrid& g) { game::applyEdit(g, op); });
        ++tried;
        if (r.changedCells == 0) continue;
        ASSERT_TRUE(r.undoable) << "edit " << tried;
        ++changed;
    }
    const BrickGrid end = grid;
    EXPECT_FALSE(end == start);
    EXPECT_EQ(history.stats().undoSteps, changed);
    std::printf("undo history after %zu edits: %.2f MiB\n", changed,
                double(history.stats().bytes) / kMiB);

    while (history.canUndo()) ASSERT_FALSE(history.undo(grid).empty());
    expectSameCells(grid, start);
    EXPECT_EQ(history.stats().redoSteps, changed);
    while (history.canRedo()) ASSERT_FALSE(history.redo(grid).empty());
    expectSameCells(grid, end);
    // And back once more: the swap keeps both directions exact.
    while (history.canUndo()) history.undo(grid);
    expectSameCells(grid, start);
}

TEST(UndoHistory, StoresChangedBricksNotTheWorld) {
    BrickGrid grid({256, 64, 256});
    fillBox(grid, Box{{0, 0, 0}, {256, 24, 256}}, 1);  // a world of homogeneous cells
    grid.clearDirty();
    UndoHistory history(64 * kMiB);
    EditOp op;
    op.tool = game::Tool::Place;
    op.box = {{100, 30, 100}, {101, 31, 101}};  // in an empty cell
    op.material = 2;
    game::EditRecord r = history.record(grid, op.region(), "one voxel",
                                        [&](BrickGrid& g) { game::applyEdit(g, op); });
    EXPECT_EQ(r.changedCells, 1u);
    // One empty cell's state (a material id) and bookkeeping: far below one brick, let alone
    // the world.
    EXPECT_LT(history.stats().bytes, 1024u);
    EXPECT_EQ(grid.dirtyCells().size(), 1u);

    // Painting the top of the ground splits uniform cells: the undo step holds their old
    // state (uniform, a few bytes each), not copies of the bricks.
    op.tool = game::Tool::Paint;
    op.box = {{0, 23, 0}, {64, 24, 64}};
    r = history.record(grid, op.region(), "paint", [&](BrickGrid& g) { game::applyEdit(g, op); });
    EXPECT_EQ(r.changedCells, 64u);
    EXPECT_LT(history.stats().bytes, 4096u);
    history.undo(grid);
    // After the undo the step holds the 64 painted bricks, to redo them.
    EXPECT_GE(history.stats().bytes, 64u * sizeof(BrickVoxels));
    EXPECT_LT(history.stats().bytes, 80u * sizeof(BrickVoxels));
}

TEST(UndoHistory, MemoryStaysWithinTheBudgetByDroppingTheOldestSteps) {
    BrickGrid grid = testing_worlds::makeWorld(testing_worlds::Kind::Dense, 3, {64, 32, 64});
    const std::size_t budget = 256 * 1024;
    UndoHistory history(budget);
    engine::Rng rng(11);
    for (int i = 0; i < 300; ++i) {
        EditOp op = randomEdit(rng, grid.sizeInVoxels());
        history.record(grid, op.region(), "edit", [&](BrickGrid& g) { game::applyEdit(g, op); });
        ASSERT_LE(history.stats().bytes, budget) << "after edit " << i;
    }
    game::UndoStats s = history.stats();
    EXPECT_GT(s.droppedSteps, 0u);
    EXPECT_GT(s.undoSteps, 0u);
    EXPECT_EQ(s.maxBytes, budget);
    while (history.canUndo()) {
        history.undo(grid);
        ASSERT_LE(history.stats().bytes, budget);
    }
    // Shrinking the budget drops steps at once.
    history.setMaxBytes(4096);
    EXPECT_LE(history.stats().bytes, 4096u);
}

TEST(UndoHistory, AnEditLargerThanTheBudgetIsAppliedButNotUndoable) {
    BrickGrid grid = testing_worlds::makeWorld(testing_worlds::Kind::Dense, 5, {64, 32, 64});
    UndoHistory history(16 * 1024);
    EditOp op;
    op.tool = game::Tool::Paint;
    op.box = grid.bounds();
    op.material = 6;
    game::EditRecord r = history.record(grid, op.region(), "paint all",
                                        [&](BrickGrid& g) { game::applyEdit(g, op); });
    EXPECT_GT(r.changedCells, 16u);
    EXPECT_FALSE(r.undoable);
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.stats().bytes, 0u);
    EXPECT_EQ(history.stats().droppedSteps, 1u);
}

TEST(UndoHistory, ANewEditClearsRedoAndUnchangedEditsRecordNothing) {
    BrickGrid grid({32, 32, 32});
    UndoHistory history(kMiB);
    EditOp op;
    op.box = {{1, 1, 1}, {2, 2, 2}};
    op.material = 1;
    history.record(grid, op.region(), "a", [&](BrickGrid& g) { game::applyEdit(g, op); });
    game::EditRecord same =
        history.record(grid, op.region(), "again", [&](BrickGrid& g) { game::applyEdit(g, op); });
    EXPECT_EQ(same.changedCells, 0u);
    EXPECT_EQ(history.stats().undoSteps, 1u);
    EXPECT_EQ(history.undo(grid), "a");
    EXPECT_TRUE(history.canRedo());
    op.box = {{5, 5, 5}, {6, 6, 6}};
    history.record(grid, op.region(), "b", [&](BrickGrid& g) { game::applyEdit(g, op); });
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(grid.get({1, 1, 1}), kEmpty);
    EXPECT_EQ(grid.get({5, 5, 5}), 1);
}
