#include "world/bridge_generator.h"

#include "world/world_edits.h"

namespace engine::world {

namespace {

struct Axes {
    int along, across;
};

Axes axesOf(const BridgeParams& p) {
    glm::ivec3 size = p.max - p.min;
    return size.x >= size.z ? Axes{0, 2} : Axes{2, 0};
}

// Positions along the deck that get a light: every lightSpacing, offset by half a spacing so
// that no light sits at an end.
template <typename F>
void forEachLight(const BridgeParams& p, F&& f) {
    if (p.lightSpacing <= 0 || p.light == kEmpty) return;
    Axes ax = axesOf(p);
    if (p.max[ax.across] - p.min[ax.across] < 4) return;
    for (int t = p.min[ax.along] + p.lightSpacing / 2; t < p.max[ax.along]; t += p.lightSpacing) {
        for (int side : {p.min[ax.across] + 1, p.max[ax.across] - 2}) f(t, side);
    }
}

}  // namespace

int bridgeLightCount(const BridgeParams& p) {
    int n = 0;
    forEachLight(p, [&](int, int) { ++n; });
    return n;
}

void generateBridge(BrickGrid& grid, const BridgeParams& p) {
    const Axes ax = axesOf(p);
    auto box = [&](glm::ivec3 a, glm::ivec3 b, MaterialId m) { fillBox(grid, Box{a, b}, m); };
    auto span = [&](int along0, int along1, int across0, int across1, int y0, int y1) {
        glm::ivec3 a{0}, b{0};
        a[ax.along] = along0;
        b[ax.along] = along1;
        a[ax.across] = across0;
        b[ax.across] = across1;
        a.y = y0;
        b.y = y1;
        return Box{a, b};
    };
    const int a0 = p.min[ax.along], a1 = p.max[ax.along];
    const int c0 = p.min[ax.across], c1 = p.max[ax.across];
    const int top = p.max.y;  // first voxel above the deck

    box(p.min, p.max, p.deck);
    // Two girders under the edges and a cross beam every 8 voxels.
    for (int c : {c0, c1 - 1}) {
        Box g = span(a0, a1, c, c + 1, p.min.y - 2, p.min.y);
        box(g.min, g.max, p.deck);
    }
    for (int t = a0 + 4; t < a1; t += 8) {
        Box beam = span(t, t + 1, c0, c1, p.min.y - 1, p.min.y);
        box(beam.min, beam.max, p.deck);
    }
    // Railings on both edges: posts and a top rail.
    if (p.railing != kEmpty && p.railingHeight > 0) {
        for (int c : {c0, c1 - 1}) {
            for (int t = a0; t < a1; t += p.postSpacing) {
                Box post = span(t, t + 1, c, c + 1, top, top + p.railingHeight);
                box(post.min, post.max, p.railing);
            }
            Box rail = span(a0, a1, c, c + 1, top + p.railingHeight - 1, top + p.railingHeight);
            box(rail.min, rail.max, p.railing);
        }
    }
    forEachLight(p, [&](int t, int c) {
        Box light = span(t, t + 1, c, c + 1, top, top + 1);
        box(light.min, light.max, p.light);
    });
}

}  // namespace engine::world
