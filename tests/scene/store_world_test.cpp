// A world through its store and back: voxel for voxel (a generated world, a real VDB), with its
// scene keys; a scene file naming the store; a box read by its regions; an old TOML + VDB save
// converted.
#include "scene/store_world.h"

#include <gtest/gtest.h>

#include "game/world_store.h"
#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "io/vdb_test_util.h"
#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "scene/world_regions.h"
#include "world/region_store.h"

namespace {

namespace fs = std::filesystem;
using engine::world::Scene;

void expectSameWorld(const Scene& a, const Scene& b) {
    EXPECT_TRUE(a.grid == b.grid);
    EXPECT_EQ(a.grid.sizeInVoxels(), b.grid.sizeInVoxels());
    EXPECT_EQ(a.grid.liveBricks(), b.grid.liveBricks());
    EXPECT_EQ(a.grid.solidVoxels(), b.grid.solidVoxels());
    EXPECT_TRUE(a.palette == b.palette);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.voxelSize, b.voxelSize);
    ASSERT_EQ(a.cameras.size(), b.cameras.size());
    for (std::size_t i = 0; i < a.cameras.size(); ++i) {
        EXPECT_EQ(a.cameras[i].name, b.cameras[i].name);
        EXPECT_EQ(a.cameras[i].position, b.cameras[i].position);
    }
    EXPECT_EQ(a.sky.sunDirection, b.sky.sunDirection);
    EXPECT_EQ(a.indirect, b.indirect);
    EXPECT_EQ(a.objects.size(), b.objects.size());
}

TEST(StoreWorld, GeneratedWorldsRoundTripVoxelForVoxel) {
    vox_test::ScratchDir dir("gen");
    for (const char* name : {"sandbox", "terrain_1024", "cornell"}) {
        auto path = engine::scene::resolveWorldPath(name);
        ASSERT_TRUE(path.ok());
        auto scene = engine::scene::loadSceneFile(*path);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        const fs::path store = dir / (std::string(name) + ".db");
        auto report = engine::scene::writeWorldStore(*scene, store);
        ASSERT_TRUE(report.ok()) << report.error().message;
        auto back = engine::scene::loadWorldStore(store);
        ASSERT_TRUE(back.ok()) << back.error().message;
        expectSameWorld(*scene, *back);
        // Written again from what was read: the same rows (a stable format).
        auto again = engine::scene::writeWorldStore(*back, dir / "again.db");
        ASSERT_TRUE(again.ok());
        EXPECT_EQ(again->storedBytes, report->storedBytes) << name;
    }
}

TEST(StoreWorld, RealVdbRoundTripsAndExportsLikeTodaysPath) {
    const fs::path file = vox_test::sharedVdbDir() / "usd_densityAndHeat.vdb";
    if (!fs::exists(file))
        GTEST_SKIP() << "real VDB files not found at " << file.parent_path()
                     << " (../shared/data/vdb beside the checkout)";
    vox_test::ScratchDir dir("vdb");
    auto scene = engine::io::importVdb(file);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_TRUE(engine::scene::writeWorldStore(*scene, dir / "w.db").ok());
    auto back = engine::scene::loadWorldStore(dir / "w.db");
    ASSERT_TRUE(back.ok()) << back.error().message;
    expectSameWorld(*scene, *back);
    // Exported from the store, the VDB imports as the one exported from the imported world.
    ASSERT_TRUE(engine::io::exportVdb(*scene, dir / "direct.vdb").ok());
    ASSERT_TRUE(engine::io::exportVdb(*back, dir / "store.vdb").ok());
    auto a = engine::io::importVdb(dir / "direct.vdb");
    auto b = engine::io::importVdb(dir / "store.vdb");
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_TRUE(a->grid == b->grid);
    EXPECT_TRUE(a->palette == b->palette);
    // vox export's path for a store, region by region, writes the same file as the store loaded
    // whole.
    auto lean = engine::scene::loadWorldLean(dir / "w.db");
    ASSERT_TRUE(lean.ok()) << lean.error().message;
    auto regions = engine::scene::worldRegionsOf(*lean, dir / "w.db");
    ASSERT_TRUE(regions.ok() && regions->source);
    ASSERT_TRUE(engine::io::exportVdb(*lean, *regions->source, dir / "regions.vdb").ok());
    EXPECT_TRUE(vox_test::vdbBytesWithoutUuid(dir / "store.vdb") ==
                vox_test::vdbBytesWithoutUuid(dir / "regions.vdb"));
}

TEST(StoreWorld, SceneFileNamingTheStoreMapsMaterialsByName) {
    vox_test::ScratchDir dir("named");
    auto scene = engine::scene::loadSceneFile(engine::scene::resolveWorldPath("sandbox").value());
    ASSERT_TRUE(scene.ok());
    ASSERT_TRUE(engine::scene::writeWorldStore(*scene, dir / "w.db").ok());
    // The scene file lists the materials in another order, plus one of its own first.
    std::string text = "[world]\nsize = [" + std::to_string(scene->grid.sizeInVoxels().x) + ", " +
                       std::to_string(scene->grid.sizeInVoxels().y) + ", " +
                       std::to_string(scene->grid.sizeInVoxels().z) + "]\n";
    text += "\n[[material]]\nname = \"extra\"\nalbedo = [0.5, 0.5, 0.5]\n";
    const auto& materials = scene->palette.materials();
    for (std::size_t i = materials.size() - 1; i >= 1; --i)
        text += "\n[[material]]\nname = \"" + materials[i].name + "\"\nalbedo = [0.5, 0.5, 0.5]\n";
    text += "\n[[generator]]\ntype = \"store\"\nsource = \"w.db\"\n";
    auto named = engine::scene::loadSceneText(text, (dir / "w.toml").string());
    ASSERT_TRUE(named.ok()) << named.error().message;
    EXPECT_EQ(engine::scene::storeOfScene(*named), dir / "w.db");
    const glm::ivec3 s = scene->grid.sizeInVoxels();
    std::uint64_t checked = 0;
    for (int z = 0; z < s.z; z += 3)
        for (int y = 0; y < s.y; y += 2)
            for (int x = 0; x < s.x; x += 3) {
                const auto m = scene->grid.get({x, y, z});
                const auto n = named->grid.get({x, y, z});
                ASSERT_EQ(m == 0, n == 0) << x << " " << y << " " << z;
                if (m) {
                    ASSERT_EQ(scene->palette[m].name, named->palette[n].name);
                    ++checked;
                }
            }
    EXPECT_GT(checked, 0u);
}

TEST(StoreWorld, BoxReadsOnlyTheRegionsItMeets) {
    vox_test::ScratchDir dir("box");
    auto scene =
        engine::scene::loadSceneFile(engine::scene::resolveWorldPath("terrain_1024").value());
    ASSERT_TRUE(scene.ok());
    ASSERT_TRUE(engine::scene::writeWorldStore(*scene, dir / "w.db").ok());
    const engine::world::Box box{{130, 0, 260}, {300, 200, 333}};
    auto part = engine::scene::loadWorldStore(dir / "w.db", box);
    ASSERT_TRUE(part.ok()) << part.error().message;
    const glm::ivec3 lo = box.min / 8 * 8;
    EXPECT_EQ(part->grid.sizeInVoxels(), (box.max + 7) / 8 * 8 - lo);
    const glm::ivec3 s = part->grid.sizeInVoxels();
    for (int z = 0; z < s.z; z += 2)
        for (int y = 0; y < s.y; y += 2)
            for (int x = 0; x < s.x; x += 2)
                ASSERT_EQ(part->grid.get({x, y, z}), scene->grid.get(lo + glm::ivec3(x, y, z)));
}

TEST(StoreWorld, OldTomlAndVdbSaveConverts) {
    vox_test::ScratchDir dir("old");
    auto scene = engine::scene::loadSceneFile(engine::scene::resolveWorldPath("sandbox").value());
    ASSERT_TRUE(scene.ok());
    scene->grid.set({5, 5, 5}, 2);
    auto store = game::makeWorldStore();
    ASSERT_TRUE(store->save(*scene, dir / "old.toml").ok());
    auto old = engine::scene::loadSceneFile(dir / "old.toml");
    ASSERT_TRUE(old.ok()) << old.error().message;
    ASSERT_TRUE(engine::scene::writeWorldStore(*old, dir / "new.db").ok());
    auto converted = engine::scene::loadWorldStore(dir / "new.db");
    ASSERT_TRUE(converted.ok()) << converted.error().message;
    EXPECT_TRUE(converted->grid == scene->grid);
    EXPECT_TRUE(converted->palette == scene->palette);
}

}  // namespace
