#include "world/brick.h"

#include <algorithm>

namespace engine::world {

BrickMask BrickMask::build(const BrickVoxels& voxels) {
    BrickMask mask;
    for (int z = 0; z < kBrickDim; ++z) {
        for (int y = 0; y < kBrickDim; ++y) {
            for (int x = 0; x < kBrickDim; ++x) {
                int i = brickVoxelIndex({x, y, z});
                if (voxels[i] == kEmpty) continue;
                mask.words[i >> 5] |= 1u << (i & 31);
                int b2 = (x >> 1) + 4 * (y >> 1) + 16 * (z >> 1);
                mask.words[shared::MASK_COARSE_WORD + (b2 >> 5)] |= 1u << (b2 & 31);
                mask.words[shared::MASK_QUARTER_WORD] |=
                    1u << ((x >> 2) + 2 * (y >> 2) + 4 * (z >> 2));
            }
        }
    }
    return mask;
}

bool isUniform(const BrickVoxels& voxels) {
    return std::all_of(voxels.begin(), voxels.end(), [&](MaterialId m) { return m == voxels[0]; });
}

}  // namespace engine::world
