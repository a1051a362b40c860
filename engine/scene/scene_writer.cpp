// The one scene file writer of scene/scene_file.h: every table the reader knows, in the order
// worlds/README.md shows them, each value so that it reads back the same.
#include "scene/generator_registry.h"
#include "scene/indirect_keys.h"
#include "scene/path_table.h"
#include "scene/scene_file.h"
#include "scene/toml_writer.h"
#include "world/flythrough.h"

namespace engine::scene {

namespace {

using world::Scene;

void writeMaterials(const world::Palette& palette, TomlWriter& out) {
    const auto& materials = palette.materials();
    for (std::size_t i = 1; i < materials.size(); ++i) {  // 0 is the reserved "empty"
        const world::Material& m = materials[i];
        out.arrayTable("material");
        out.key("name", m.name);
        out.key("albedo", m.albedo);
        if (m.emissive()) {
            out.key("emission", m.emissionColor);
            out.key("strength", m.emissionStrength);
        }
    }
}

void writeObject(const world::DynamicObject& object,
                 const std::vector<world::GeneratorRecord>& generators,
                 const world::Palette& palette, TomlWriter& out) {
    using Given = world::ObjectKey::Given;
    out.arrayTable("object");
    out.key("name", object.name);
    out.key("size", object.modelSize);
    out.key("loop", object.path.loop());
    for (const world::GeneratorRecord& g : generators)
        writeGenerator(g, "object.generator", out, palette);
    for (const world::ObjectKey& key : object.path.keys()) {
        out.arrayTable("object.key");
        out.key("time", key.time);
        // The reader takes positions and angles as floats: these are floats widened.
        out.key("position", glm::vec3(key.position));
        if (key.given == Given::YawPitchRoll) out.key("rotation", glm::vec3(key.angles));
        if (key.given == Given::AxisAngle) {
            out.key("axis", glm::vec3(key.angles));
            out.key("angle", key.angle);
        }
    }
}

}  // namespace

std::string sceneText(const Scene& scene, const SceneWriteOptions& options) {
    TomlWriter out;
    out.comment(options.headerComment);
    out.table("world");
    out.key("name", scene.name);
    out.key("size", scene.grid.sizeInVoxels());
    out.key("voxel_size", scene.voxelSize);
    writeMaterials(scene.palette, out);
    for (const world::GeneratorRecord& g :
         options.generators ? *options.generators : scene.generators)
        writeGenerator(g, "generator", out, scene.palette);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const world::DynamicObject& object = scene.objects[i];
        writeObject(object,
                    options.objectGenerators ? (*options.objectGenerators)[i] : object.generators,
                    scene.palette, out);
    }
    for (const world::CameraPreset& c : scene.cameras) {
        out.arrayTable("camera");
        out.key("name", c.name);
        out.key("position", c.position);
        out.key("target", c.target);
        out.key("fov", c.fovYDegrees);
    }
    out.table("sky");
    out.key("sun_direction", scene.sky.sunDirection);
    out.key("sun_radiance", scene.sky.sunRadiance);
    out.key("sky_radiance", scene.sky.skyRadiance);
    if (!scene.sky.lightMode.empty()) out.key("sky_light", scene.sky.lightMode);
    writeIndirect(scene, out);
    if (scene.path) writePath(*scene.path, out);
    return out.text();
}

}  // namespace engine::scene
