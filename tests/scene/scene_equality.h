// Scene equality for the round-trip tests: everything a scene file says must come back the
// same — name, voxel size, palette, the grid voxel for voxel, dynamic objects (model voxels and
// path keys), cameras, sky, [indirect] and [path] (keys and events). Floats compare exactly.
// Left out: where a scene came from (sourcePath, an event's "file:line"), runtime state
// (dynamic poses, start times) and the generator records (the text tests cover those).
#pragma once

#include <string>

#include "world/scene.h"

namespace engine::scene::test {

// Empty when `a` and `b` are the same scene, else the first difference, in words.
std::string sceneDifference(const world::Scene& a, const world::Scene& b);

}  // namespace engine::scene::test
