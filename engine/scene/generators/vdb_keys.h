// The `vdb` generator (scene/generators/vdb_keys.cpp) for a payload written beside a scene file:
// saves (`rule = "ids"`, our own layout, voxel for voxel) and `vox import`.
#pragma once

#include <string>

#include "world/generator_record.h"

namespace engine::scene {

// `source` relative to the scene file's folder (or absolute).
world::GeneratorRecord vdbPayloadGenerator(std::string source, bool ids);

}  // namespace engine::scene
