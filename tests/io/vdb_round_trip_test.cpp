// Our own files come back exactly: every shipped world, voxel for voxel and palette for palette,
// with its name, size, voxel size, cameras and sky; homogeneous bricks travel as tiles.
#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include "core/atomic_file.h"
#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"
#include "vdb_test_util.h"
#include "world/world_edits.h"
#include "world/world_info.h"

using namespace engine;
using vox_test::ScratchDir;
namespace fs = std::filesystem;

namespace {

void expectSameScene(const world::Scene& a, const world::Scene& b, const std::string& what) {
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a.grid.sizeInVoxels(), b.grid.sizeInVoxels()) << what;
    EXPECT_TRUE(a.grid == b.grid) << what << ": voxels differ";
    EXPECT_TRUE(a.palette == b.palette) << what << ": palettes differ";
    EXPECT_EQ(a.voxelSize, b.voxelSize) << what;
    ASSERT_EQ(a.cameras.size(), b.cameras.size()) << what;
    for (std::size_t i = 0; i < a.cameras.size(); ++i) {
        EXPECT_EQ(a.cameras[i].name, b.cameras[i].name) << what;
        EXPECT_EQ(a.cameras[i].position, b.cameras[i].position) << what;
        EXPECT_EQ(a.cameras[i].target, b.cameras[i].target) << what;
        EXPECT_EQ(a.cameras[i].fovYDegrees, b.cameras[i].fovYDegrees) << what;
    }
    EXPECT_EQ(a.sky.sunDirection, b.sky.sunDirection) << what;
    EXPECT_EQ(a.sky.sunRadiance, b.sky.sunRadiance) << what;
    EXPECT_EQ(a.sky.skyRadiance, b.sky.skyRadiance) << what;
}

}  // namespace

TEST(VdbRoundTrip, EveryShippedWorldComesBackExactly) {
    ScratchDir dir("rt");
    int worlds = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(VOX_SOURCE_DIR) / "worlds")) {
        if (entry.path().extension() != ".toml") continue;
        auto scene = engine::scene::loadSceneFile(entry.path());
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        const fs::path file = dir / (entry.path().stem().string() + ".vdb");
        io::VdbExportReport exported;
        Status s = io::exportVdb(*scene, file, {}, &exported);
        ASSERT_TRUE(s.ok()) << s.error().message;
        EXPECT_EQ(exported.solidVoxels, scene->grid.solidVoxels());

        io::VdbImportReport report;
        auto back = io::importVdb(file, {}, &report);
        ASSERT_TRUE(back.ok()) << back.error().message;
        expectSameScene(*scene, *back, entry.path().filename().string());
        EXPECT_EQ(report.solidVoxels, scene->grid.solidVoxels());
        EXPECT_EQ(report.plan.kind, "voxengine world");
        // The plan's memory estimate bounds what the import really allocated.
        EXPECT_LE(report.peakTrackedBytes, report.plan.estimateBytes) << entry.path();
        ++worlds;
    }
    EXPECT_GE(worlds, 3);
}

TEST(VdbRoundTrip, ImportedSceneFileLoadsTheSameWorld) {
    // What `vox import -o WORLD.toml` writes: a scene file naming the .vdb payload.
    ScratchDir dir("toml");
    auto scene = engine::scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "sandbox.toml");
    ASSERT_TRUE(scene.ok());
    ASSERT_TRUE(io::exportVdb(*scene, dir / "sandbox.vdb").ok());
    std::vector<world::GeneratorRecord> payload{
        engine::scene::vdbPayloadGenerator("sandbox.vdb", false)};
    std::string text =
        engine::scene::sceneText(*scene, {.headerComment = "test", .generators = &payload});
    std::ofstream(dir / "sandbox.toml") << text;
    auto loaded = engine::scene::loadSceneFile(dir / "sandbox.toml");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->grid == scene->grid);
    EXPECT_TRUE(loaded->palette == scene->palette);
    EXPECT_EQ(loaded->cameras.size(), scene->cameras.size());
    EXPECT_EQ(loaded->sourcePath,
              (dir / "sandbox.toml").string());  // the scene file, not the payload
    EXPECT_TRUE(loaded->grid.dirtyBricks().empty());
}

TEST(VdbRoundTrip, HomogeneousCellsAreTilesAndBricksAreLeaves) {
    ScratchDir dir("tiles");
    auto scene = engine::scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    ASSERT_TRUE(scene.ok());
    io::VdbExportReport report;
    ASSERT_TRUE(io::exportVdb(*scene, dir / "c.vdb", {}, &report).ok());
    const world::WorldInfo info = world::describeWorld(*scene);
    EXPECT_EQ(report.tiles, info.homogeneousCells);
    EXPECT_EQ(report.leaves, info.bricks);

    openvdb::initialize();
    openvdb::io::File file((dir / "c.vdb").string());
    file.open();
    auto ids = openvdb::gridPtrCast<openvdb::Int32Grid>(file.readGrid("material"));
    ASSERT_TRUE(ids);
    EXPECT_EQ(ids->tree().leafCount(), info.bricks);
    EXPECT_EQ(ids->tree().activeTileCount(), info.homogeneousCells);
    EXPECT_EQ(ids->activeVoxelCount(), scene->grid.solidVoxels());
    EXPECT_DOUBLE_EQ(ids->voxelSize().x(), double(scene->voxelSize));
    // The albedo grid shows each voxel's colour to other tools; emission only where it glows.
    auto albedo = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("albedo"));
    auto emission = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("emission"));
    ASSERT_TRUE(albedo && emission);
    EXPECT_EQ(albedo->activeVoxelCount(), ids->activeVoxelCount());
    EXPECT_EQ(emission->activeVoxelCount(), scene->emissiveVoxels());
    for (auto it = ids->cbeginValueOn(); it; ++it) {
        const world::Material& m = scene->palette[world::MaterialId(*it)];
        openvdb::Vec3s a = albedo->tree().getValue(it.getCoord());
        ASSERT_EQ(glm::vec3(a.x(), a.y(), a.z()), m.albedo);
        if (it.isTileValue()) continue;
        break;  // one leaf voxel is enough once the tiles have been checked
    }
}

TEST(VdbRoundTrip, EmptyAndOddSizedWorldsComeBack) {
    ScratchDir dir("odd");
    world::Scene scene;
    scene.name = "odd \"quoted\" name";
    scene.voxelSize = 0.125f;
    scene.grid = world::BrickGrid(glm::ivec3(13, 5, 40));
    ASSERT_TRUE(io::exportVdb(scene, dir / "empty.vdb").ok());
    auto back = io::importVdb(dir / "empty.vdb");
    ASSERT_TRUE(back.ok()) << back.error().message;
    expectSameScene(scene, *back, "empty");

    auto rock = *scene.palette.add({"rock", glm::vec3(0.3f, 0.2f, 0.1f), glm::vec3(0.0f), 0.0f});
    auto glow = *scene.palette.add({"glow", glm::vec3(1.0f), glm::vec3(0.2f, 0.4f, 1.0f), 7.5f});
    world::fillSphere(scene.grid, glm::vec3(6.0f, 2.0f, 20.0f), 9.0f, rock);
    scene.grid.set(glm::ivec3(12, 4, 39), glow);
    scene.grid.set(glm::ivec3(0, 0, 0), glow);
    ASSERT_TRUE(io::exportVdb(scene, dir / "odd.vdb").ok());
    back = io::importVdb(dir / "odd.vdb");
    ASSERT_TRUE(back.ok()) << back.error().message;
    expectSameScene(scene, *back, "odd");
}

TEST(VdbRoundTrip, FailedExportLeavesThePreviousFileIntact) {
    ScratchDir dir("atomic");
    auto scene = engine::scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    ASSERT_TRUE(scene.ok());
    const fs::path file = dir / "keep.vdb";
    std::ofstream(file) << "previous contents";
    // Block the temporary file's name with a directory, so the write fails before the rename.
    fs::create_directory(engine::temporaryPathFor(file));
    Status s = io::exportVdb(*scene, file);
    ASSERT_FALSE(s.ok());
    EXPECT_TRUE(vox_test::isOneLineNamingFile(s.error().message, file));
    std::ifstream in(file);
    std::string contents((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(contents, "previous contents");
}

// `vox export --for blender`: a float fog grid other tools can use, a transform that stands the
// world up along +z, and still the exact world when it comes back.
TEST(VdbRoundTrip, ExportForBlenderIsZUpWithADensityGridAndComesBackExactly) {
    ScratchDir dir("blender");
    auto scene = engine::scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    ASSERT_TRUE(scene.ok());
    auto options = io::vdbExportOptionsFor("blender");
    ASSERT_TRUE(options.ok());
    io::VdbExportReport report;
    ASSERT_TRUE(io::exportVdb(*scene, dir / "b.vdb", *options, &report).ok());
    ASSERT_FALSE(report.grids.empty());
    EXPECT_EQ(report.grids[0], "density");

    // What OpenVDB itself reads (as Blender, vdb_render and pyopenvdb do).
    openvdb::initialize();
    openvdb::io::File file((dir / "b.vdb").string());
    file.open();
    auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    ASSERT_TRUE(density);
    EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
    EXPECT_EQ(density->activeVoxelCount(), scene->grid.solidVoxels());
    float lo = 2.0f, hi = -1.0f;
    for (auto it = density->cbeginValueOn(); it; ++it)
        lo = std::min(lo, *it), hi = std::max(hi, *it);
    EXPECT_EQ(lo, 1.0f);
    EXPECT_EQ(hi, 1.0f);
    // The engine's +y (index j) is the file's world +z, its +z the file's -y.
    const double s = double(scene->voxelSize);
    const openvdb::Vec3d up = density->indexToWorld(openvdb::Vec3d(0, 1, 0));
    const openvdb::Vec3d forward = density->indexToWorld(openvdb::Vec3d(0, 0, 1));
    const openvdb::Vec3d right = density->indexToWorld(openvdb::Vec3d(1, 0, 0));
    EXPECT_TRUE(up.eq(openvdb::Vec3d(0, 0, s))) << up;
    EXPECT_TRUE(forward.eq(openvdb::Vec3d(0, -s, 0))) << forward;
    EXPECT_TRUE(right.eq(openvdb::Vec3d(s, 0, 0))) << right;
    auto material = file.readGrid("material");
    EXPECT_TRUE(material->transform() == density->transform());
    file.close();

    io::VdbImportReport imported;
    auto back = io::importVdb(dir / "b.vdb", {}, &imported);
    ASSERT_TRUE(back.ok()) << back.error().message;
    expectSameScene(*scene, *back, "blender export");
    EXPECT_EQ(imported.plan.grid, "material") << "import keeps using the lossless grid";
    EXPECT_FALSE(imported.plan.upZ) << "index space is ours: nothing to turn";

    auto houdini = io::vdbExportOptionsFor("houdini");
    ASSERT_TRUE(houdini.ok());
    EXPECT_TRUE(houdini->densityGrid);
    EXPECT_FALSE(houdini->zUp);
    EXPECT_FALSE(io::vdbExportOptionsFor("maya").ok());
}
