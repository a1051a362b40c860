// What a scene file said to build part of a grid: a generator's type and its parsed parameters.
// The world keeps these beside the voxels they made so a scene file can be written back; the
// parameter types belong to the layer that reads scene files (engine/scene/generator_registry.h),
// which is above this one, so they are held type-erased here and read back only there.
#pragma once

#include <any>
#include <string>

namespace engine::world {

struct GeneratorRecord {
    std::string type;  // "terrain", "box", "vdb", ...
    std::any params;   // the registry entry's parameter struct for `type`
};

}  // namespace engine::world
