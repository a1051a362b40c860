// A scene written back as text loads to the same palette, voxel size, cameras and sky, floats
// exact.
#include <gtest/gtest.h>

#include "world/scene_file.h"
#include "world/scene_file_writer.h"

using namespace engine::world;

TEST(SceneFileWriter, BuiltInWorldsRoundTripWithoutTheirGenerators) {
    for (const char* name : {"sandbox", "cornell"}) {
        auto path = resolveWorldPath(name);
        ASSERT_TRUE(path.ok());
        auto scene = loadSceneFile(*path);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        std::string text = sceneTextWithPalette(*scene, "", "written by a test");
        auto back = loadSceneText(text, "roundtrip.toml");
        ASSERT_TRUE(back.ok()) << back.error().message << "\n" << text;
        EXPECT_EQ(back->name, scene->name);
        EXPECT_EQ(back->grid.sizeInVoxels(), scene->grid.sizeInVoxels());
        EXPECT_TRUE(back->palette == scene->palette) << name;
        ASSERT_EQ(back->cameras.size(), scene->cameras.size());
        for (std::size_t i = 0; i < scene->cameras.size(); ++i) {
            EXPECT_EQ(back->cameras[i].position, scene->cameras[i].position);
            EXPECT_EQ(back->cameras[i].target, scene->cameras[i].target);
            EXPECT_EQ(back->cameras[i].fovYDegrees, scene->cameras[i].fovYDegrees);
        }
        EXPECT_EQ(back->sky.sunRadiance, scene->sky.sunRadiance);
        EXPECT_EQ(back->sky.skyRadiance, scene->sky.skyRadiance);
        EXPECT_LT(glm::length(back->sky.sunDirection - scene->sky.sunDirection), 1e-6f);
    }
}

TEST(SceneFileWriter, QuotesNamesAndKeepsFloatsExact) {
    Scene scene;
    scene.name = "a \"quoted\" \\ name\twith tab";
    Material m;
    m.name = "odd \"name\"";
    m.albedo = {0.1f, 1.0f / 3.0f, 0.7f};
    m.emissionColor = {1.0f, 0.5f, 0.25f};
    m.emissionStrength = 3.0f;
    scene.palette.add(m);
    scene.cameras.push_back({"c", {1e-3f, 123456.7f, -0.1f}, {2.0f, 2.0f, 2.0f}, 60.0f});
    scene.voxelSize = 0.1f;
    auto back = loadSceneText(sceneTextWithPalette(scene, ""), "t.toml");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->name, scene.name);
    EXPECT_EQ(back->voxelSize, scene.voxelSize);
    EXPECT_TRUE(back->palette == scene.palette);
    EXPECT_EQ(back->cameras[0].position, scene.cameras[0].position);
    EXPECT_EQ(tomlString("x\"y"), "\"x\\\"y\"");
}
