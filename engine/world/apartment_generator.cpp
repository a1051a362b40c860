#include "world/apartment_generator.h"

#include <algorithm>

#include "core/hash.h"
#include "world/world_edits.h"

namespace engine::world {

namespace {

// One facade: the wall plane at `plane` along `normalAxis`, facing `outward` (+1/-1), windows
// running along `alongAxis` between `from` and `to`.
struct Facade {
    int normalAxis, alongAxis;
    int plane, outward;
    int from, to;
};

}  // namespace

void generateApartment(BrickGrid& grid, const ApartmentParams& p) {
    Rng rng(p.seed);
    const glm::ivec3 lo = p.min, hi = p.min + p.size;
    auto box = [&](glm::ivec3 a, glm::ivec3 b, MaterialId m) { fillBox(grid, Box{a, b}, m); };

    // Shell, then the inside hollowed storey by storey, leaving a slab at each floor.
    box(lo, hi, p.wall);
    const int storeys = std::max(1, (p.size.y - 1) / p.storey);
    for (int s = 0; s < storeys; ++s) {
        int y0 = lo.y + s * p.storey + 1, y1 = std::min(lo.y + (s + 1) * p.storey, hi.y - 1);
        box({lo.x + 1, y0, lo.z + 1}, {hi.x - 1, y1, hi.z - 1}, kEmpty);
    }
    box({lo.x, lo.y, lo.z}, {hi.x, lo.y + 1, hi.z}, p.slab);
    for (int s = 1; s <= storeys; ++s) {
        int y = std::min(lo.y + s * p.storey, hi.y - 1);
        box({lo.x + 1, y, lo.z + 1}, {hi.x - 1, y + 1, hi.z - 1}, p.slab);
    }
    // A stair core in the middle keeps the block from being see-through.
    glm::ivec3 coreSize{std::max(3, p.size.x / 4), 0, std::max(3, p.size.z / 4)};
    glm::ivec3 coreLo{lo.x + (p.size.x - coreSize.x) / 2, lo.y, lo.z + (p.size.z - coreSize.z) / 2};
    box(coreLo, {coreLo.x + coreSize.x, hi.y, coreLo.z + coreSize.z}, p.wall);

    // Roof: parapet and a stair house.
    box({lo.x, hi.y, lo.z}, {hi.x, hi.y + 1, hi.z}, p.wall);
    box({lo.x + 1, hi.y, lo.z + 1}, {hi.x - 1, hi.y + 1, hi.z - 1}, kEmpty);
    box({coreLo.x - 1, hi.y, coreLo.z - 1},
        {coreLo.x + coreSize.x + 1, hi.y + 5, coreLo.z + coreSize.z + 1}, p.wall);

    // Windows and balconies, facade by facade.
    const Facade facades[] = {
        {2, 0, lo.z, -1, lo.x, hi.x},
        {2, 0, hi.z - 1, +1, lo.x, hi.x},
        {0, 2, lo.x, -1, lo.z, hi.z},
        {0, 2, hi.x - 1, +1, lo.z, hi.z},
    };
    const int ww = p.windowSize.x, wh = std::min(p.windowSize.y, p.storey - 3);
    for (const Facade& f : facades) {
        const int span = f.to - f.from - 4;
        const int count = std::max(0, (span - ww) / p.windowSpacing + 1);
        const int start =
            f.from + 2 + (span - ((count - 1) * p.windowSpacing + ww)) / 2;  // centred
        for (int s = 0; s < storeys; ++s) {
            int y = lo.y + s * p.storey + 2;
            for (int w = 0; w < count; ++w) {
                glm::ivec3 a{0}, b{0};
                a[f.normalAxis] = f.plane;
                b[f.normalAxis] = f.plane + 1;
                a[f.alongAxis] = start + w * p.windowSpacing;
                b[f.alongAxis] = a[f.alongAxis] + ww;
                a.y = y;
                b.y = y + wh;
                bool lit = rng.nextFloat() < p.lit && !p.windowLights.empty();
                MaterialId light = p.windowLights.empty()
                                       ? kEmpty
                                       : p.windowLights[rng.nextU32() % p.windowLights.size()];
                bool balcony = rng.nextFloat() < p.balconies;
                box(a, b, lit ? light : kEmpty);
                if (lit || !balcony || p.railing == kEmpty) continue;
                // A ledge one voxel below the opening, two deep, with a railing on its edge.
                glm::ivec3 la = a, lb = b;
                la[f.alongAxis] -= 1;
                lb[f.alongAxis] += 1;
                la[f.normalAxis] = f.outward > 0 ? f.plane + 1 : f.plane - 2;
                lb[f.normalAxis] = la[f.normalAxis] + 2;
                la.y = y - 1;
                lb.y = y;
                box(la, lb, p.slab);
                glm::ivec3 ra = la, rb = lb;
                ra[f.normalAxis] = f.outward > 0 ? lb[f.normalAxis] - 1 : la[f.normalAxis];
                rb[f.normalAxis] = ra[f.normalAxis] + 1;
                ra.y = y;
                rb.y = y + 2;
                box(ra, rb, p.railing);
            }
        }
    }

    // Neon strips down the four vertical edges.
    if (p.cornerLight != kEmpty) {
        for (int cx : {lo.x, hi.x - 1})
            for (int cz : {lo.z, hi.z - 1})
                box({cx, lo.y, cz}, {cx + 1, hi.y, cz + 1}, p.cornerLight);
    }

    // The rock underneath: layers shrinking by a random 0..3 voxels per side, like an inverted
    // stepped cone torn out of the ground.
    if (p.base != kEmpty) {
        glm::ivec3 a{lo.x + 1, lo.y - 1, lo.z + 1}, b{hi.x - 1, lo.y, hi.z - 1};
        for (int d = 0; d < p.baseDepth && a.x < b.x && a.z < b.z; ++d) {
            box(a, b, p.base);
            a.y -= 1;
            b.y -= 1;
            a.x += rng.uniformInt(0, 3);
            a.z += rng.uniformInt(0, 3);
            b.x -= rng.uniformInt(0, 3);
            b.z -= rng.uniformInt(0, 3);
        }
    }
}

}  // namespace engine::world
