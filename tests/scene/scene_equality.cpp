// Scene equality for the round-trip tests (scene/scene_equality.h).
#include "scene/scene_equality.h"

#include <fmt/format.h>

#include "world/flythrough.h"

namespace engine::scene::test {

using namespace engine::world;

namespace {

std::string pathDifference(const Flythrough& a, const Flythrough& b) {
    if (a.fps != b.fps) return fmt::format("path fps {} vs {}", a.fps, b.fps);
    if (a.duration != b.duration)
        return fmt::format("path duration {} vs {}", a.duration, b.duration);
    const auto& ka = a.camera.keys();
    const auto& kb = b.camera.keys();
    if (ka.size() != kb.size()) return fmt::format("{} vs {} path keys", ka.size(), kb.size());
    for (std::size_t i = 0; i < ka.size(); ++i) {
        if (ka[i].time != kb[i].time || ka[i].position != kb[i].position ||
            ka[i].target != kb[i].target || ka[i].fovYDegrees != kb[i].fovYDegrees)
            return fmt::format("path key {} differs", i);
    }
    const auto& ea = a.timeline.events();
    const auto& eb = b.timeline.events();
    if (ea.size() != eb.size()) return fmt::format("{} vs {} path events", ea.size(), eb.size());
    for (std::size_t i = 0; i < ea.size(); ++i) {
        const TimelineEvent &x = ea[i], &y = eb[i];
        bool same = x.kind == y.kind && x.time == y.time && x.material == y.material &&
                    x.box.min == y.box.min && x.box.max == y.box.max &&
                    x.wholeWorld == y.wholeWorld && x.center == y.center && x.radius == y.radius &&
                    x.voxel == y.voxel && x.on == y.on && x.object == y.object;
        if (!same) return fmt::format("path event {} ({}) differs", i, x.where);
    }
    return {};
}

std::string objectDifference(const DynamicObject& a, const DynamicObject& b) {
    if (a.name != b.name) return fmt::format("object '{}' vs '{}'", a.name, b.name);
    std::string what = fmt::format("object '{}': ", a.name);
    if (a.modelSize != b.modelSize) return what + "model size";
    if (!(*a.model == *b.model)) return what + "model voxels";
    if (a.path.loop() != b.path.loop()) return what + "loop";
    const auto& ka = a.path.keys();
    const auto& kb = b.path.keys();
    if (ka.size() != kb.size()) return what + fmt::format("{} vs {} keys", ka.size(), kb.size());
    for (std::size_t i = 0; i < ka.size(); ++i) {
        if (ka[i].time != kb[i].time || ka[i].position != kb[i].position ||
            ka[i].rotation != kb[i].rotation)
            return what + fmt::format("key {} differs", i);
    }
    return {};
}

}  // namespace

std::string sceneDifference(const Scene& a, const Scene& b) {
    if (a.name != b.name) return fmt::format("name '{}' vs '{}'", a.name, b.name);
    if (a.voxelSize != b.voxelSize)
        return fmt::format("voxel size {} vs {}", a.voxelSize, b.voxelSize);
    if (!(a.palette == b.palette)) return "palette";
    if (a.grid.sizeInVoxels() != b.grid.sizeInVoxels()) return "world size";
    if (!(a.grid == b.grid)) return "grid voxels";
    if (a.objects.size() != b.objects.size())
        return fmt::format("{} vs {} objects", a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        if (std::string d = objectDifference(a.objects[i], b.objects[i]); !d.empty()) return d;
    }
    if (a.cameras.size() != b.cameras.size())
        return fmt::format("{} vs {} cameras", a.cameras.size(), b.cameras.size());
    for (std::size_t i = 0; i < a.cameras.size(); ++i) {
        const CameraPreset &x = a.cameras[i], &y = b.cameras[i];
        if (x.name != y.name || x.position != y.position || x.target != y.target ||
            x.fovYDegrees != y.fovYDegrees)
            return fmt::format("camera '{}' differs", x.name);
    }
    if (a.sky.sunDirection != b.sky.sunDirection || a.sky.sunRadiance != b.sky.sunRadiance ||
        a.sky.skyRadiance != b.sky.skyRadiance || a.sky.lightMode != b.sky.lightMode)
        return "sky";
    if (a.indirect != b.indirect) return "[indirect] settings";
    if (bool(a.path) != bool(b.path))
        return a.path ? "the second has no [path]" : "the first has no [path]";
    if (a.path) return pathDifference(*a.path, *b.path);
    return {};
}

}  // namespace engine::scene::test
