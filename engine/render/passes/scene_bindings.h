// The buffers every ray-tracing pass binds before its own: the world (WORLD_BINDING_*) and, for
// the passes that sample lights, the emitter list (LIGHTS_BINDING_*); shaders/shared/bindings.h
// numbers them.
#pragma once

#include <array>

#include "render/gpu_emitter_list.h"
#include "render/gpu_world.h"
#include "render/passes/compute_pass.h"

namespace engine::render {

struct SceneBindings {
    const GpuWorld& world;
    const GpuEmitterList& lights;
};

std::array<PassBinding, 5> worldBindings(const GpuWorld& world);
std::array<PassBinding, 9> sceneBindings(const SceneBindings& scene);  // world, then emitter list

}  // namespace engine::render
