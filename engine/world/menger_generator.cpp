#include "world/menger_generator.h"

#include "world/world_edits.h"

namespace engine::world {

namespace {

// Carves the three axis tunnels through the middle third of the cube at `lo` with edge
// 3 * third, then recurses into the 20 sub-cubes that remain.
void carve(BrickGrid& grid, glm::ivec3 lo, int third, int levels, int scale) {
    if (levels == 0 || third < scale) return;
    const int edge = 3 * third;
    for (int axis = 0; axis < 3; ++axis) {
        glm::ivec3 a = lo + third, b = lo + 2 * third;
        a[axis] = lo[axis];
        b[axis] = lo[axis] + edge;
        fillBox(grid, Box{a, b}, kEmpty);
    }
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) {
                if ((x == 1) + (y == 1) + (z == 1) >= 2) continue;  // a tunnel or the centre
                carve(grid, lo + glm::ivec3(x, y, z) * third, third / 3, levels - 1, scale);
            }
}

}  // namespace

long long mengerVoxelCount(const MengerParams& p) {
    long long n = 1;
    for (int i = 0; i < p.level; ++i) n *= 20;
    return n * p.scale * p.scale * p.scale;
}

void generateMenger(BrickGrid& grid, const MengerParams& p) {
    const int edge = mengerEdge(p);
    fillBox(grid, Box{p.origin, p.origin + edge}, p.material);
    carve(grid, p.origin, edge / 3, p.level, p.scale);
}

}  // namespace engine::world
