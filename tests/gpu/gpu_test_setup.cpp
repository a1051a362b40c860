// The GPU tests' shared frame setup (gpu_test_setup.h).
#include "gpu/gpu_test_setup.h"

#include <cmath>
#include <filesystem>

#include "scene/scene_file.h"

namespace gpu_testing {

FrameSettings frame(std::uint32_t width, std::uint32_t height) {
    FrameSettings f;
    f.width = width;
    f.height = height ? height : width;
    return f;
}

engine::world::Scene loadWorld(const std::string& name) {
    std::filesystem::path path = std::filesystem::path(VOX_SOURCE_DIR) / "worlds" / name;
    if (path.extension() != ".toml") path += ".toml";
    auto scene = engine::scene::loadSceneFile(path);
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error().message);
    return scene.ok() ? std::move(scene).value() : engine::world::Scene{};
}

engine::world::Scene paletteScene(glm::ivec3 size,
                                  std::initializer_list<engine::world::Material> materials,
                                  bool darkSky) {
    engine::world::Scene scene;
    scene.grid = engine::world::BrickGrid(size);
    for (const engine::world::Material& m : materials) (void)scene.palette.add(m);
    if (darkSky) {
        scene.sky.sunRadiance = glm::vec3(0.0f);
        scene.sky.skyRadiance = glm::vec3(0.0f);
    }
    return scene;
}

FrameImages renderOnce(engine::world::Scene& scene, const engine::world::CameraPreset& camera,
                       const FrameSettings& settings, const LightingSettings& lighting) {
    Renderer renderer(context());
    renderer.render(scene, camera, settings, lighting);
    return renderer.readback();
}

FrameImages renderFrames(Renderer& renderer, engine::world::Scene& scene,
                         const LightingSettings& lighting, const FrameSettings& settings,
                         int frames) {
    for (int i = 0; i < frames; ++i) renderer.render(scene, scene.camera(), settings, lighting);
    return renderer.readback();
}

double meanLuminance(const std::vector<glm::vec4>& image) {
    double sum = 0.0;
    for (const glm::vec4& p : image) sum += luminance(p);
    return sum / double(image.size());
}

double mae(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += std::abs(a[i].x - b[i].x) + std::abs(a[i].y - b[i].y) + std::abs(a[i].z - b[i].z);
    return sum / (3.0 * double(a.size()));
}

}  // namespace gpu_testing
