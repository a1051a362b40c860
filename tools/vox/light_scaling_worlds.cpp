#include "light_scaling_worlds.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace vox {

const char* layoutName(LightLayout layout) {
    return layout == LightLayout::Dense ? "dense" : "sparse";
}

LightScalingWorld lightScalingWorld(LightLayout layout, std::uint32_t count) {
    const int extent = kLightWorldExtent;
    const int perSide = std::max(1, int(std::lround(std::sqrt(double(count)))));
    // Dense: a lamp per 2x2 voxels over perSide^2 cells around the centre. Sparse: perSide^2
    // cells over the whole floor (the spacing rounds, so the count is near, not at, N).
    const int spacing =
        layout == LightLayout::Dense ? 2 : std::max(1, int(std::lround(double(extent) / perSide)));
    const int footprint = std::min(extent, layout == LightLayout::Dense ? 2 * perSide : extent);
    const int margin = (extent - footprint) / 2;
    const std::uint64_t cells = std::uint64_t((extent - 2 * margin) / spacing);
    LightScalingWorld w;
    w.name = fmt::format("lights_{}_{}", layoutName(layout), count);
    w.lamps = cells * cells;
    const int c = extent / 2;
    w.toml = fmt::format(
        R"(# Written by `vox bench lights`: {0} single-voxel lamps {1} on a {2}x{2} floor.
[world]
name = "{3}"
size = [{2}, {4}, {2}]

[[material]]
name = "floor"
albedo = [0.5, 0.5, 0.5]

[[material]]
name = "lamp"
albedo = [0.9, 0.9, 0.9]
emission = [1.0, 0.85, 0.7]
strength = 4.0

[[generator]]
type = "box"
min = [0, 0, 0]
max = [{2}, 1, {2}]
material = "floor"

[[generator]]
type = "scattered_lights"
spacing = {5}
size = [1, 1, 1]
margin = {6}
seed = 38
light = "lamp"

[[camera]]
name = "view"
position = [{7}, 12, {8}]
target = [{7}, 0, {9}]
fov = 60

# Night: no sun and a faint sky, so the lamps carry the scene.
[sky]
sun_direction = [0.3, 0.6, -0.5]
sun_radiance = [0.0, 0.0, 0.0]
sky_radiance = [0.01, 0.01, 0.015]
)",
        w.lamps,
        layout == LightLayout::Dense ? fmt::format("every {} voxels around the view", spacing)
                                     : fmt::format("one per {0}x{0} voxels", spacing),
        extent, w.name, kLightWorldHeight, spacing, margin, c, c - 48, c + 16);
    return w;
}

}  // namespace vox
