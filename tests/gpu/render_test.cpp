// The frame: G-buffer against the CPU reference traversal, determinism, and image files.
#include <algorithm>
#include <bit>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "core/memory_budget.h"
#include "gpu/gpu_test_setup.h"
#include "gpu/texel_buffer_limit.h"
#include "io/image_io.h"
#include "scene/scene_file.h"
#include "world/random_worlds.h"

using namespace engine::world;
using namespace engine::scene;
using namespace gpu_testing;

class Render : public GpuTest {};

TEST_F(Render, GBufferMatchesCpuTraversalPerPixel) {
    Scene scene = loadWorld("sandbox.toml");
    const FrameSettings settings = frame(128, 72);
    CameraPreset camera = scene.camera();
    FrameImages img = renderOnce(scene, camera, settings);
    shared::FrameParams params = engine::render::makeFrameParams(camera, scene.sky, settings);
    int hits = 0, mismatches = 0;
    for (std::uint32_t y = 0; y < settings.height; ++y)
        for (std::uint32_t x = 0; x < settings.width; ++x) {
            Ray ray{camera.position, engine::render::cameraRayDirection(params, {x, y})};
            RayHit cpu = traceRay(scene.grid, ray);
            const shared::GBufferTexel& g = img.gbuffer[x + y * settings.width];
            bool gpuHit = std::uint32_t(g.voxel.w) != shared::FACE_NONE;
            hits += cpu.hit;
            bool same =
                gpuHit == cpu.hit &&
                (!cpu.hit || (glm::ivec3(g.voxel) == cpu.voxel && g.data.x == cpu.material));
            if (same) continue;
            ++mismatches;
            // The camera direction is normalised on both sides; a last-bit difference may only
            // matter where the ray grazes an edge.
            EXPECT_LT(testing_worlds::nearestEdgeDistance(ray, cpu.hit ? cpu.t + 1.0f : 2000.0f),
                      1e-3f)
                << "pixel " << x << "," << y;
        }
    std::printf("G-buffer vs CPU: %d pixels, %d hits, %d mismatches\n",
                settings.width * settings.height, hits, mismatches);
    EXPECT_GT(hits, int(settings.width * settings.height) / 3);
    EXPECT_LE(mismatches * 1000, int(settings.width * settings.height));
}

TEST_F(Render, SameInputsGiveTheSameImage) {
    Scene scene = loadWorld("cornell.toml");
    FrameImages ia = renderOnce(scene, scene.camera(), frame(64)),
                ib = renderOnce(scene, scene.camera(), frame(64));
    EXPECT_EQ(ia.rgba8, ib.rgba8);
    EXPECT_EQ(0, std::memcmp(ia.radiance.data(), ib.radiance.data(),
                             ia.radiance.size() * sizeof(glm::vec4)));
}

TEST_F(Render, EmissiveLightIsBrighterThanAlbedoAndSkyMatchesItsColour) {
    Scene scene = loadWorld("cornell.toml");
    FrameImages img = renderOnce(scene, scene.camera(), frame(64));
    MaterialId light = *scene.palette.find("light");
    int lightPixels = 0;
    for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
        if (img.gbuffer[i].data.x != light ||
            std::uint32_t(img.gbuffer[i].voxel.w) != shared::FACE_NEG_X + 2)
            continue;
        ++lightPixels;
        // Face -Y of the ceiling light: radiance = emission + albedo x ambient.
        glm::vec3 expected = scene.palette[light].emittedRadiance() +
                             scene.palette[light].albedo * scene.sky.skyRadiance * (0.55f - 0.45f);
        EXPECT_NEAR(img.radiance[i].x, expected.x, 1e-4f);
        EXPECT_NEAR(img.radiance[i].z, expected.z, 1e-4f);
    }
    EXPECT_GT(lightPixels, 20);
}

TEST_F(Render, PngAndExrFilesRoundTrip) {
    Scene scene = loadWorld("sandbox.toml");
    FrameImages img = renderOnce(scene, scene.camera(), frame(48, 32));
    auto dir = std::filesystem::temp_directory_path() / "vox_render_test";
    std::filesystem::create_directories(dir);
    ASSERT_TRUE(engine::io::writeExr(dir / "frame.exr", img.width, img.height, img.radiance).ok());
    auto back = engine::io::readExr(dir / "frame.exr");
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->pixels.size(), img.radiance.size());
    EXPECT_EQ(0, std::memcmp(back->pixels.data(), img.radiance.data(),
                             img.radiance.size() * sizeof(glm::vec4)));
    ASSERT_TRUE(engine::io::writePng(dir / "frame.png", img.width, img.height, img.rgba8).ok());
    std::ifstream png(dir / "frame.png", std::ios::binary);
    char magic[8] = {};
    png.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
    // A failed write leaves the previous file alone.
    auto bad = engine::io::writePng(dir / "frame.png", img.width + 1, img.height, img.rgba8);
    EXPECT_FALSE(bad.ok());
    EXPECT_TRUE(std::filesystem::exists(dir / "frame.png"));
    std::filesystem::remove_all(dir);
}

// A world whose GPU copy and frame buffers would not fit in the memory budget is refused with the
// plan before any of it is allocated, and the renderer stays usable for a world that fits.
TEST_F(Render, AWorldOverTheMemoryBudgetIsRefusedBeforeItsGpuCopy) {
    Scene scene = loadWorld("sandbox.toml");
    const FrameSettings settings = frame(64, 48);
    engine::render::Renderer renderer(gpu_testing::context());
    engine::setMemoryBudgetBytes(1ull << 20);
    EXPECT_THROW(
        {
            try {
                renderer.render(scene, scene.camera(), settings, kPreview);
            } catch (const engine::MemoryBudgetExceeded& e) {
                EXPECT_NE(std::string(e.what()).find("over the memory budget of 1 MiB"),
                          std::string::npos)
                    << e.what();
                throw;
            }
        },
        engine::MemoryBudgetExceeded);
    engine::setMemoryBudgetBytes(0);  // the default
    auto result = renderer.render(scene, scene.camera(), settings, kPreview);
    EXPECT_TRUE(result.upload.full);
}

// A world whose grid texels (cells, super cells, brick masks) would not fit one texel view is
// refused with its count and the device's limit before its GPU copy changes, and the renderer
// stays usable for a world that fits (the limit lowered for the test: a world over lavapipe's
// 2^27 texels takes gigabytes).
TEST_F(Render, AWorldOverTheTexelLimitIsRefusedWithItsSize) {
    Scene scene = loadWorld("sandbox.toml");
    const FrameSettings settings = frame(64, 48);
    engine::render::Renderer renderer(gpu_testing::context());
    gpu_testing::context().limitTexelBuffers(50000);
    EXPECT_THROW(
        {
            try {
                renderer.render(scene, scene.camera(), settings, kPreview);
            } catch (const engine::gpu::TexelBufferTooLarge& e) {
                // Super cells, region table, room for the cell pages (doubling, at least 8),
                // the mask copy.
                const std::string texels = std::to_string(
                    scene.grid.superCells().size() + scene.grid.topGrid().table().size() +
                    std::max<std::size_t>(8, std::bit_ceil(scene.grid.topGrid().pageCount())) *
                        4096 +
                    4096 * 20 * ((scene.grid.brickCapacity() + 4095) / 4096));
                EXPECT_NE(std::string(e.what()).find(
                              "world 'sandbox' too large for the GPU's texel buffer: " + texels +
                              " texels, limit 50000"),
                          std::string::npos)
                    << e.what();
                throw;
            }
        },
        engine::gpu::TexelBufferTooLarge);
    gpu_testing::context().limitTexelBuffers(0);  // the device's
    auto result = renderer.render(scene, scene.camera(), settings, kPreview);
    EXPECT_TRUE(result.upload.full);
}
