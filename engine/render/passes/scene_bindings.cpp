#include "render/passes/scene_bindings.h"

#include "shared/bindings.h"

namespace engine::render {

std::array<PassBinding, 5> worldBindings(const GpuWorld& world) {
    return {{{shared::WORLD_BINDING_INFO, &world.info()},
             {shared::WORLD_BINDING_CELLS, &world.cells()},
             {shared::WORLD_BINDING_PAGES, &world.pageTable()},
             {shared::WORLD_BINDING_PALETTE, &world.palette()},
             {shared::WORLD_BINDING_DYNAMIC, &world.dynamicGridTexels()}}};
}

std::array<PassBinding, 9> sceneBindings(const SceneBindings& scene) {
    return joinBindings(
        worldBindings(scene.world),
        std::to_array<PassBinding>({{shared::LIGHTS_BINDING_INFO, &scene.lights.info()},
                                    {shared::LIGHTS_BINDING_EMITTERS, &scene.lights.emitters()},
                                    {shared::LIGHTS_BINDING_ALIVE, &scene.lights.alive()},
                                    {shared::LIGHTS_BINDING_ALIAS, &scene.lights.alias()}}));
}

}  // namespace engine::render
