// Where source voxels land in an OpenVDB import (io/vdb_import.h). Source index i -> oriented j
// (axis switch: a permutation with signs, each voxel's unit cube [i, i+1) mapped onto [j, j+1))
// -> world continuous u = j * scale + offset. Plus the box conversions between OpenVDB's
// inclusive CoordBBox and our max-exclusive Box. Internal to engine/io.
#pragma once

#include <cmath>
#include <cstdint>
#include <openvdb/openvdb.h>

#include "io/vdb_import.h"
#include "world/scene.h"

namespace engine::io::vdb_import {

using world::Box;

inline Box toBox(const openvdb::CoordBBox& b) {
    return {glm::ivec3(b.min().x(), b.min().y(), b.min().z()),
            glm::ivec3(b.max().x(), b.max().y(), b.max().z()) + 1};
}
inline openvdb::CoordBBox toCoordBBox(const Box& b) {
    return openvdb::CoordBBox(openvdb::Coord(b.min.x, b.min.y, b.min.z),
                              openvdb::Coord(b.max.x - 1, b.max.y - 1, b.max.z - 1));
}
// Widened to whole leaves: OpenVDB's clip turns every tile that a clip box cuts into a dense leaf
// (2 KiB for floats), so an unaligned box would fill its whole boundary with leaves.
openvdb::CoordBBox leafAligned(const Box& b);
// The source box an import may take voxels from: the crop option, or everything.
Box cropBox(const VdbImportOptions& options);
Box unite(const Box& a, const Box& b);
std::uint64_t volume(const Box& b);
inline int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

struct AxisMap {
    int perm[3] = {0, 1, 2};  // world axis a reads source axis perm[a]
    int sign[3] = {1, 1, 1};
    glm::dvec3 scale{1.0};   // world voxels per source voxel, per world axis
    glm::dvec3 offset{0.0};  // world position of oriented voxel 0's corner
    bool exact = true;       // scale 1 and whole-voxel offset: a voxel-for-voxel copy

    glm::ivec3 toSource(glm::ivec3 j) const {
        glm::ivec3 i;
        for (int a = 0; a < 3; ++a) i[perm[a]] = sign[a] > 0 ? j[a] : -j[a] - 1;
        return i;
    }
    // Continuous, voxel centres at integers (OpenVDB's index space).
    glm::dvec3 toSourceCentre(glm::dvec3 j) const {
        glm::dvec3 i;
        for (int a = 0; a < 3; ++a) i[perm[a]] = sign[a] > 0 ? j[a] : -j[a] - 1.0;
        return i;
    }
    Box orient(const Box& s) const {
        Box j;
        for (int a = 0; a < 3; ++a) {
            int p = perm[a];
            j.min[a] = sign[a] > 0 ? s.min[p] : -s.max[p];
            j.max[a] = sign[a] > 0 ? s.max[p] : -s.min[p];
        }
        return j;
    }
    Box unorient(const Box& j) const {
        Box s;
        for (int a = 0; a < 3; ++a) {
            int p = perm[a];
            s.min[p] = sign[a] > 0 ? j.min[a] : -j.max[a];
            s.max[p] = sign[a] > 0 ? j.max[a] : -j.min[a];
        }
        return s;
    }
    // World voxels touched by an oriented box, widened by `margin` world voxels.
    Box span(const Box& j, double margin) const {
        Box w;
        for (int a = 0; a < 3; ++a) {
            w.min[a] = int(std::floor(j.min[a] * scale[a] + offset[a] - margin));
            w.max[a] = int(std::ceil(j.max[a] * scale[a] + offset[a] + margin));
        }
        return w;
    }
    // World voxels whose centre lies inside an oriented box, shrunk by `margin` world voxels.
    Box centresInside(const Box& j, double margin) const {
        Box w;
        for (int a = 0; a < 3; ++a) {
            w.min[a] = int(std::ceil(j.min[a] * scale[a] + offset[a] + margin - 0.5));
            w.max[a] = int(std::ceil(j.max[a] * scale[a] + offset[a] - margin - 0.5));
        }
        return w;
    }
    // Oriented voxels any sampling of the world box may read (nearest, footprint or trilinear).
    Box needed(const Box& w) const {
        if (exact) return Box{w.min - glm::ivec3(offset), w.max - glm::ivec3(offset)};
        Box j;
        for (int a = 0; a < 3; ++a) {
            j.min[a] = int(std::floor((w.min[a] - offset[a]) / scale[a])) - 1;
            j.max[a] = int(std::ceil((w.max[a] - offset[a]) / scale[a])) + 2;
        }
        return j;
    }
    // Exact mappings: the world voxel of source voxel i.
    glm::ivec3 exactTarget(glm::ivec3 i) const {
        glm::ivec3 j;
        for (int a = 0; a < 3; ++a) j[a] = sign[a] > 0 ? i[perm[a]] : -i[perm[a]] - 1;
        return j + glm::ivec3(offset);
    }
    glm::ivec3 nearest(glm::ivec3 t) const {
        if (exact) return t - glm::ivec3(offset);
        glm::ivec3 j;
        for (int a = 0; a < 3; ++a) j[a] = int(std::floor((t[a] + 0.5 - offset[a]) / scale[a]));
        return j;
    }
    glm::dvec3 centre(glm::ivec3 t) const {  // oriented, continuous, voxel centres at integers
        glm::dvec3 x;
        for (int a = 0; a < 3; ++a) x[a] = (t[a] + 0.5 - offset[a]) / scale[a] - 0.5;
        return x;
    }
    // Oriented voxels whose centres lie in world voxel t (inclusive); the nearest one on axes
    // where the world is finer than the source.
    void footprint(glm::ivec3 t, glm::ivec3& lo, glm::ivec3& hi) const {
        glm::ivec3 n = nearest(t);
        for (int a = 0; a < 3; ++a) {
            lo[a] = int(std::ceil((t[a] - offset[a]) / scale[a] - 0.5));
            hi[a] = int(std::ceil((t[a] + 1 - offset[a]) / scale[a] - 0.5)) - 1;
            if (hi[a] < lo[a]) lo[a] = hi[a] = n[a];
        }
    }
};

// The placement of one import, worked out by the steps in vdb_import_placement.cpp.
struct Placement {
    AxisMap map;
    bool trilinear =
        false;  // level set, finer world on every axis: sample the distance trilinearly
    bool footprint = false;  // level set, coarser world on some axis: solid if any source voxel is
    Box sourceBox;           // source index box imported
    Box worldBox;            // where it lands, clipped to the world
    glm::ivec3 worldSize{0};
};

}  // namespace engine::io::vdb_import
