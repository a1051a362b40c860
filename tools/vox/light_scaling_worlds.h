// vox bench lights' worlds: one floor, the same camera, and N single-voxel lamps laid out
// (a) densely near the camera — lamps every 2 voxels over a square around the view's centre that
//     grows with N, so what the view sees nearby stays the same and only the far lights grow — or
// (b) sparsely over the whole floor — one lamp per cell of a grid whose spacing shrinks with N,
//     so the lights the view sees nearby get closer as N grows.
// Written as scene files (box + scattered_lights generators, seeded), so each world can be
// rendered on its own (`vox render FILE --timings T.json`) and the path tracer's reference cache
// keys on its text.
#pragma once

#include <cstdint>
#include <string>

namespace vox {

enum class LightLayout { Dense, Sparse };

struct LightScalingWorld {
    std::string name;         // lights_<layout>_<count>
    std::string toml;         // the scene file
    std::uint64_t lamps = 0;  // lamps the generator places (grid cells): about the count asked
};

inline constexpr int kLightWorldExtent = 2048;  // floor edge in voxels (x and z)
inline constexpr int kLightWorldHeight = 32;

const char* layoutName(LightLayout layout);
LightScalingWorld lightScalingWorld(LightLayout layout, std::uint32_t count);

}  // namespace vox
