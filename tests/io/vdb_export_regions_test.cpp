// VDB export region by region (io/vdb_export.h, io/vdb_export_cells.h): from a world store or a
// terrain scene file the file is byte for byte the one exported from the whole world in memory,
// each region is read once per pass, and a damaged region fails with one line and leaves no file.
#include <fstream>
#include <gtest/gtest.h>

#include "io/vdb_export.h"
#include "io/vdb_test_util.h"
#include "scene/scene_file.h"
#include "scene/store_world.h"
#include "scene/world_regions.h"
#include "world/region_store.h"
#include "world/store_region_source.h"
#include "world/test_terrain.h"

namespace {

namespace fs = std::filesystem;
using namespace engine::world;

// 47 x 25 x 42 cells: 3 x 2 x 3 regions, clipped at every far edge; stone glows, so the file
// has an emission grid whose content differs from the material grid's.
Scene terrainScene() {
    Scene s;
    s.name = "export_regions";
    s.grid = BrickGrid(glm::ivec3(376, 200, 336));
    Material grass{.name = "grass", .albedo = {0.2f, 0.4f, 0.1f}};
    Material dirt{.name = "dirt", .albedo = {0.4f, 0.3f, 0.2f}};
    Material stone{.name = "stone", .albedo = {0.5f, 0.5f, 0.5f}};
    stone.emissionColor = {1.0f, 0.8f, 0.6f};
    stone.emissionStrength = 2.0f;
    s.palette.add(grass);
    s.palette.add(dirt);
    s.palette.add(stone);
    generateTerrain(s.grid, vox_test::testTerrain());
    return s;
}

TEST(VdbExportRegions, FromAStoreTheFileIsTheWholeWorldsByteForByte) {
    vox_test::ScratchDir dir("vdb_export_regions");
    const Scene scene = terrainScene();
    ASSERT_TRUE(engine::scene::writeWorldStore(scene, dir / "w.db").ok());
    engine::io::VdbExportReport whole, streamed;
    ASSERT_TRUE(engine::io::exportVdb(scene, dir / "whole.vdb", {}, &whole).ok());

    auto lean = engine::scene::loadWorldLean(dir / "w.db");
    ASSERT_TRUE(lean.ok()) << lean.error().message;
    EXPECT_EQ(lean->grid.liveBricks(), 0u);  // the export below reads no voxel from the scene
    auto regions = engine::scene::worldRegionsOf(*lean, dir / "w.db");
    ASSERT_TRUE(regions.ok() && regions->source) << regions.error().message;
    auto written = engine::io::exportVdb(*lean, *regions->source, dir / "store.vdb", {}, &streamed);
    ASSERT_TRUE(written.ok()) << written.error().message;

    EXPECT_EQ(whole.grids, streamed.grids);
    ASSERT_EQ(streamed.grids.size(), 3u);  // material, albedo, emission
    EXPECT_TRUE(vox_test::vdbBytesWithoutUuid(dir / "whole.vdb") ==
                vox_test::vdbBytesWithoutUuid(dir / "store.vdb"));
    // Per grid: every region once for the statistics, the regions with content once for the
    // topology and once for the buffers — never the world at once, never a region per cell.
    EXPECT_LE(streamed.regionLoads, 3u * 3u * 18u);
    EXPECT_GE(streamed.regionLoads, 3u * 18u);
}

TEST(VdbExportRegions, FromATerrainSceneFileTheFileIsTheGeneratedWorlds) {
    vox_test::ScratchDir dir("vdb_export_terrain");
    const fs::path file = dir / "t.toml";
    std::ofstream(file) << R"([world]
name = "t"
size = [376, 200, 336]

[[material]]
name = "grass"
albedo = [0.2, 0.4, 0.1]

[[material]]
name = "dirt"
albedo = [0.4, 0.3, 0.2]

[[material]]
name = "stone"
albedo = [0.5, 0.5, 0.5]

[[generator]]
type = "terrain"
top = "grass"
soil = "dirt"
rock = "stone"
base_height = 96
amplitude = 64
wavelength = 90
octaves = 4
seed = 11
)";
    auto whole = engine::scene::loadSceneFile(file);
    ASSERT_TRUE(whole.ok()) << whole.error().message;
    ASSERT_GT(whole->grid.liveBricks(), 0u);
    ASSERT_TRUE(engine::io::exportVdb(*whole, dir / "whole.vdb").ok());

    auto lean = engine::scene::loadWorldLean(file);
    ASSERT_TRUE(lean.ok()) << lean.error().message;
    auto regions = engine::scene::worldRegionsOf(*lean, file);
    ASSERT_TRUE(regions.ok() && regions->source) << regions.error().message;
    EXPECT_TRUE(regions->store.empty());
    ASSERT_TRUE(engine::io::exportVdb(*lean, *regions->source, dir / "regions.vdb").ok());
    EXPECT_TRUE(vox_test::vdbBytesWithoutUuid(dir / "whole.vdb") ==
                vox_test::vdbBytesWithoutUuid(dir / "regions.vdb"));
}

TEST(VdbExportRegions, ADamagedRegionFailsWithOneLineAndLeavesNoFile) {
    vox_test::ScratchDir dir("vdb_export_damaged");
    const Scene scene = terrainScene();
    ASSERT_TRUE(engine::scene::writeWorldStore(scene, dir / "w.db").ok());
    {
        auto store = RegionStore::open(dir / "w.db", /*writable=*/true);
        ASSERT_TRUE(store.ok()) << store.error().message;
        StoreCommit damage;
        damage.put.push_back({RegionKey{1, 0, 1}, 4096, std::vector<std::uint8_t>(40, 0x5a)});
        ASSERT_TRUE(store->commit(damage).ok());
    }
    auto lean = engine::scene::loadWorldLean(dir / "w.db");
    ASSERT_TRUE(lean.ok()) << lean.error().message;
    auto regions = engine::scene::worldRegionsOf(*lean, dir / "w.db");
    ASSERT_TRUE(regions.ok() && regions->source);
    auto written = engine::io::exportVdb(*lean, *regions->source, dir / "out.vdb");
    ASSERT_FALSE(written.ok());
    const std::string& message = written.error().message;
    EXPECT_NE(message.find("w.db"), std::string::npos) << message;
    EXPECT_NE(message.find("(1, 0, 1)"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_FALSE(fs::exists(dir / "out.vdb"));
}

}  // namespace
