// [[generator]] type = "sphere": a filled ball through world/world_edits.h.
#include "scene/generator_registry.h"
#include "world/world_edits.h"
#include "world/world_limits.h"

namespace engine::scene {

namespace {

struct SphereParams {
    glm::vec3 center{0.0f};
    float radius = 8.0f;
    world::MaterialId material = world::kEmpty;
};

SphereParams parse(GeneratorKeys& g) {
    SphereParams p;
    p.center = g.vec3("center", {}, world::kCoordinateRange, true);
    p.radius = static_cast<float>(
        g.number("radius", p.radius, aboveRange(0.0, world::kMaxWorldExtent, "voxels")));
    p.material = g.material("material");
    return p;
}

Status run(const SphereParams& p, world::Scene& scene) {
    world::fillSphere(scene.grid, p.center, p.radius, p.material);
    return {};
}

void write(const SphereParams& p, const GeneratorWriter& out) {
    out.toml.key("center", p.center);
    out.toml.key("radius", p.radius);
    out.material("material", p.material);
}

}  // namespace

extern const GeneratorEntry kSphereGenerator =
    makeGeneratorEntry<SphereParams, parse, run, write>("sphere");

}  // namespace engine::scene
