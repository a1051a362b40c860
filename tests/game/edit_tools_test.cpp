// The pick finds the voxel under the crosshair; each tool and brush edits what it should.
#include "game/edit_tools.h"

#include <gtest/gtest.h>
#include <limits>
#include <utility>

#include "world/world_edits.h"

using namespace engine::world;
using game::Brush;
using game::EditTools;
using game::Tool;

namespace {

BrickGrid ground() {
    BrickGrid grid({64, 32, 64});
    fillBox(grid, Box{{0, 0, 0}, {64, 10, 64}}, 1);
    grid.clearDirty();
    return grid;
}

// Looking straight down at (x, z) from above.
game::Pick lookDown(const BrickGrid& grid, float x, float z) {
    return game::pick(grid, {x, 30.0f, z}, {0.0f, -1.0f, 0.0f});
}

}  // namespace

TEST(EditTools, PickReportsTheVoxelAndTheFaceHit) {
    BrickGrid grid = ground();
    game::Pick p = lookDown(grid, 10.5f, 20.5f);
    ASSERT_TRUE(p.hit);
    EXPECT_EQ(p.voxel, glm::ivec3(10, 9, 20));
    EXPECT_EQ(p.normal, glm::ivec3(0, 1, 0));
    EXPECT_EQ(p.material, 1);
    EXPECT_EQ(p.adjacent(), glm::ivec3(10, 10, 20));
    EXPECT_FALSE(game::pick(grid, {10.5f, 30.0f, 20.5f}, {0.0f, 1.0f, 0.0f}).hit);  // the sky
    game::Pick side = game::pick(grid, {-5.0f, 5.5f, 3.5f}, {1.0f, 0.0f, 0.0f});
    ASSERT_TRUE(side.hit);
    EXPECT_EQ(side.voxel, glm::ivec3(0, 5, 3));
    EXPECT_EQ(side.normal, glm::ivec3(-1, 0, 0));
}

TEST(EditTools, PlaceRemovePaintOneVoxel) {
    BrickGrid grid = ground();
    EditTools tools;
    tools.material = 2;
    auto place = tools.press(lookDown(grid, 10.5f, 20.5f));
    ASSERT_TRUE(place);
    game::applyEdit(grid, *place);
    EXPECT_EQ(grid.get({10, 10, 20}), 2);  // on top of the face hit
    EXPECT_FALSE(tools.release(lookDown(grid, 10.5f, 20.5f)));

    tools.tool = Tool::Paint;
    tools.material = 3;
    game::applyEdit(grid, *tools.press(lookDown(grid, 10.5f, 20.5f)));
    EXPECT_EQ(grid.get({10, 10, 20}), 3);  // the placed voxel, repainted
    EXPECT_EQ(grid.get({10, 11, 20}), kEmpty);

    tools.tool = Tool::Remove;
    game::applyEdit(grid, *tools.press(lookDown(grid, 10.5f, 20.5f)));
    EXPECT_EQ(grid.get({10, 10, 20}), kEmpty);
    EXPECT_EQ(grid.get({10, 9, 20}), 1);
}

TEST(EditTools, BoxBrushSpansPressAndReleaseCorners) {
    BrickGrid grid = ground();
    EditTools tools;
    tools.brush = Brush::Box;
    tools.material = 4;
    EXPECT_FALSE(tools.press(lookDown(grid, 5.5f, 5.5f)));
    EXPECT_TRUE(tools.dragging());
    auto preview = tools.preview(lookDown(grid, 8.5f, 12.5f));
    ASSERT_TRUE(preview);
    auto op = tools.release(lookDown(grid, 8.5f, 12.5f));
    ASSERT_TRUE(op);
    EXPECT_EQ(op->box.min, glm::ivec3(5, 10, 5));
    EXPECT_EQ(op->box.max, glm::ivec3(9, 11, 13));
    EXPECT_EQ(preview->min, op->box.min);
    EXPECT_EQ(preview->max, op->box.max);
    game::applyEdit(grid, *op);
    EXPECT_EQ(grid.get({7, 10, 9}), 4);
    EXPECT_EQ(grid.get({9, 10, 9}), kEmpty);

    // Painting a box leaves the air in it empty.
    tools.tool = Tool::Paint;
    tools.material = 5;
    tools.press(lookDown(grid, 0.5f, 0.5f));
    op = tools.release(lookDown(grid, 20.5f, 20.5f));
    ASSERT_TRUE(op);
    op->box.max.y = 12;  // reach above the ground too
    game::applyEdit(grid, *op);
    EXPECT_EQ(grid.get({3, 9, 3}), 5);
    EXPECT_EQ(grid.get({3, 10, 3}), kEmpty);
    EXPECT_EQ(grid.get({7, 10, 9}), 5);
}

TEST(EditTools, SphereBrushAndEyedropper) {
    BrickGrid grid = ground();
    EditTools tools;
    tools.brush = Brush::Sphere;
    tools.tool = Tool::Remove;
    tools.radius = 3.0f;
    auto op = tools.press(lookDown(grid, 32.5f, 32.5f));
    ASSERT_TRUE(op);
    game::applyEdit(grid, *op);
    EXPECT_EQ(grid.get({32, 9, 32}), kEmpty);
    EXPECT_EQ(grid.get({32, 7, 32}), kEmpty);
    EXPECT_EQ(grid.get({32, 5, 32}), 1);
    Box r = op->region();
    EXPECT_TRUE(r.contains({29, 9, 32}) && r.contains({35, 9, 32}));

    grid.set({3, 10, 3}, 6);
    tools.material = 1;
    EXPECT_TRUE(tools.eyedrop(lookDown(grid, 3.5f, 3.5f)));
    EXPECT_EQ(tools.material, 6);
    EXPECT_FALSE(tools.eyedrop(game::pick(grid, {3.5f, 30.0f, 3.5f}, {0.0f, 1.0f, 0.0f})));
}

// A NaN or infinite camera gives a view ray that is not finite: it picks nothing (it used to
// "hit" voxel (0, 0, 0), and a click edited there), and the sandbox can say why.
TEST(EditTools, PickRefusesARayThatIsNotFinite) {
    BrickGrid grid = ground();
    fillBox(grid, Box{{0, 0, 0}, {1, 1, 1}}, 2);  // something at (0, 0, 0) to hit by mistake
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (auto [origin, direction] :
         {std::pair{glm::vec3(nan, 30.0f, 5.0f), glm::vec3(0.0f, -1.0f, 0.0f)},
          std::pair{glm::vec3(5.0f, 30.0f, 5.0f), glm::vec3(0.0f, nan, 0.0f)},
          std::pair{glm::vec3(inf, 30.0f, 5.0f), glm::vec3(0.0f, -1.0f, 0.0f)},
          std::pair{glm::vec3(5.0f, 30.0f, 5.0f), glm::vec3(0.0f)}}) {
        game::Pick p = game::pick(grid, origin, direction);
        EXPECT_FALSE(p.hit);
        EXPECT_FALSE(p.validRay);
        EXPECT_NE(game::missReason(p).find("not finite"), std::string::npos) << game::missReason(p);
        EditTools tools;
        EXPECT_FALSE(tools.press(p));
    }
    EXPECT_EQ(game::missReason(lookDown(grid, 10.5f, 20.5f)), "");  // a hit: nothing to explain
    game::Pick sky = game::pick(grid, {10.5f, 30.0f, 20.5f}, {0.0f, 1.0f, 0.0f});
    EXPECT_NE(game::missReason(sky).find("aiming at the sky"), std::string::npos);
}

// A box drag released over the sky has no second corner: no edit (it used to place the anchor
// voxel silently).
TEST(EditTools, BoxReleasedOverTheSkyEditsNothing) {
    BrickGrid grid = ground();
    EditTools tools;
    tools.brush = Brush::Box;
    EXPECT_FALSE(tools.press(lookDown(grid, 10.5f, 20.5f)));
    EXPECT_TRUE(tools.dragging());
    game::Pick sky = game::pick(grid, {10.5f, 30.0f, 20.5f}, {0.0f, 1.0f, 0.0f});
    EXPECT_FALSE(tools.release(sky));
    EXPECT_FALSE(tools.dragging());
}

// An edit that changes nothing says why: outside the world, or nothing to do there.
TEST(EditTools, UnchangedEditsSayWhy) {
    BrickGrid grid = ground();
    Palette palette;
    ASSERT_TRUE(palette.add(Material{"stone"}));
    game::EditOp op;
    op.tool = Tool::Place;
    op.material = 1;
    op.box = Box{{100, 5, 5}, {101, 6, 6}};
    EXPECT_EQ(game::unchangedReason(grid, op, palette),
              "it lies outside the world (0..64, 0..32, 0..64)");
    op.box = Box{{5, 5, 5}, {6, 6, 6}};
    EXPECT_EQ(game::unchangedReason(grid, op, palette), "every voxel there is already stone");
    op.tool = Tool::Remove;
    op.box = Box{{5, 20, 5}, {6, 21, 6}};
    EXPECT_EQ(game::unchangedReason(grid, op, palette), "there is nothing to remove there");
}
