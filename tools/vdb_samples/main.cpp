// make_vdb_samples: writes the foreign sample files of vdb_samples.h, for shell tests, the fuzz
// seed corpus and memory measurements.
//   make_vdb_samples seeds DIR               every sample, small
//   make_vdb_samples sphere OUT RADIUS       a level-set sphere of RADIUS voxels
//   make_vdb_samples fog-cube OUT N          fog of 1.0 over [0,N)^3, tiles only (N a multiple of
//   128) make_vdb_samples NAME OUT                one sample: fog-box wrong-types empty-grid
//   rotated
//                                            frustum non-uniform giant-tile tower ids gradient
//                                            instances duplicate-names mantaflow-tower
#include <cstdio>
#include <cstdlib>
#include <string>

#include "vdb_samples.h"

int main(int argc, char** argv) {
    namespace s = vox::samples;
    if (argc < 3) {
        std::fprintf(stderr, "usage: make_vdb_samples seeds DIR | sphere OUT RADIUS | NAME OUT\n");
        return 2;
    }
    const std::string what = argv[1];
    const s::fs::path out = argv[2];
    if (what == "seeds")
        s::writeSeedCorpus(out);
    else if (what == "sphere" && argc == 4)
        s::writeLevelSetSphere(out, std::strtof(argv[3], nullptr));
    else if (what == "fog-cube" && argc == 4)
        s::writeFogCube(out, std::atoi(argv[3]));
    else if (what == "instances")
        s::writeGridInstances(out);
    else if (what == "duplicate-names")
        s::writeDuplicateNames(out);
    else if (what == "mantaflow-tower")
        s::writeMantaflowTower(out, true);
    else if (what == "fog-box")
        s::writeFogBox(out, glm::ivec3(-5, 0, 3), glm::ivec3(11, 6, 20));
    else if (what == "wrong-types")
        s::writeWrongTypes(out);
    else if (what == "empty-grid")
        s::writeEmptyGrid(out);
    else if (what == "rotated")
        s::writeRotatedGrid(out);
    else if (what == "frustum")
        s::writeFrustumGrid(out);
    else if (what == "non-uniform")
        s::writeNonUniformGrid(out);
    else if (what == "giant-tile")
        s::writeGiantTile(out);
    else if (what == "tower")
        s::writeZUpTower(out, "");
    else if (what == "ids")
        s::writeIdGrid(out);
    else if (what == "gradient")
        s::writeColourGradient(out, 16);
    else {
        std::fprintf(stderr, "make_vdb_samples: unknown sample '%s'\n", what.c_str());
        return 2;
    }
    return 0;
}
