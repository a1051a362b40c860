// Generators run within the process's memory budget: a world too large for it fails to load with
// one line naming the file and generator, instead of aborting in an allocation (a valid
// 8192 x 256 x 8192 terrain used to die with an uncaught std::bad_alloc under ulimit -v).
#include "core/memory_budget.h"

#include <gtest/gtest.h>
#include <string>

#include "scene/scene_file.h"

namespace {

const char* kWideTerrain = R"([world]
size = [4096, 64, 4096]
[[material]]
name = "a"
[[generator]]
type = "terrain"
top = "a"
soil = "a"
rock = "a"
base_height = 20
amplitude = 16
)";

struct BudgetScope {
    explicit BudgetScope(std::uint64_t bytes) { engine::setMemoryBudgetBytes(bytes); }
    ~BudgetScope() { engine::setMemoryBudgetBytes(0); }  // back to the default
};

}  // namespace

TEST(SceneMemoryBudget, AGeneratorOverTheBudgetFailsWithOneLine) {
    BudgetScope budget(64ull << 20);
    auto scene = engine::scene::loadSceneText(kWideTerrain, "wide.toml");
    ASSERT_FALSE(scene.ok());
    const std::string& message = scene.error().message;
    EXPECT_NE(message.find(
                  "wide.toml:5: generator 'terrain' needs more memory than the budget of 64 MiB"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SceneMemoryBudget, TheSameWorldLoadsWithinADefaultBudget) {
    auto scene = engine::scene::loadSceneText(kWideTerrain, "wide.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_GT(scene->grid.liveBricks(), 0u);
}
