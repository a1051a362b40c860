#include "vdb_samples.h"

#include <cmath>
#include <numbers>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "io/vdb_export.h"
#include "world/generators.h"
#include "world/scene.h"
#include "world/world_edits.h"

namespace vox::samples {

namespace vdb = openvdb;

namespace {

void write(const fs::path& path, const vdb::GridPtrVec& grids,
           const vdb::MetaMap& meta = vdb::MetaMap(),
           std::uint32_t compression = vdb::io::COMPRESS_ACTIVE_MASK | vdb::io::COMPRESS_BLOSC) {
    vdb::initialize();
    vdb::io::File file(path.string());
    file.setCompression(compression);
    file.write(grids, meta);
    file.close();
}

vdb::FloatGrid::Ptr fogBox(glm::ivec3 min, glm::ivec3 max) {
    auto grid = vdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setGridClass(vdb::GRID_FOG_VOLUME);
    auto box = [](glm::ivec3 a, glm::ivec3 b) {
        return vdb::CoordBBox(vdb::Coord(a.x, a.y, a.z), vdb::Coord(b.x - 1, b.y - 1, b.z - 1));
    };
    grid->tree().fill(box(min - 1, max + 1), 0.25f, true);
    grid->tree().fill(box(min, max), 1.0f, true);
    return grid;
}

}  // namespace

void writeLevelSetSphere(const fs::path& path, float radiusVoxels, glm::vec3 centre,
                         double voxelSize) {
    vdb::initialize();
    const float vs = float(voxelSize);
    auto grid = vdb::tools::createLevelSetSphere<vdb::FloatGrid>(
        radiusVoxels * vs, vdb::Vec3f(centre.x, centre.y, centre.z) * vs, vs, 3.0f);
    grid->setName("surface");
    write(path, {grid});
}

void writeFogBox(const fs::path& path, glm::ivec3 min, glm::ivec3 max, double voxelSize) {
    auto grid = fogBox(min, max);
    grid->setTransform(vdb::math::Transform::createLinearTransform(voxelSize));
    write(path, {grid});
}

void writeColourGradient(const fs::path& path, int n) {
    auto grid = vdb::Vec3SGrid::create(vdb::Vec3s(0.0f));
    grid->setName("Cd");
    auto acc = grid->getAccessor();
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                acc.setValueOn(vdb::Coord(x, y, z),
                               vdb::Vec3s(float(x), float(y), float(z)) / float(n - 1));
    write(path, {grid});
}

glm::vec3 slabColour(int i) {
    static const glm::vec3 colours[6] = {{0.9f, 0.1f, 0.1f},  {0.1f, 0.8f, 0.2f},
                                         {0.15f, 0.2f, 0.9f}, {0.95f, 0.9f, 0.2f},
                                         {0.5f, 0.5f, 0.5f},  {0.05f, 0.05f, 0.05f}};
    return colours[i];
}

void writeColourSlabs(const fs::path& path) {
    auto grid = vdb::Vec3SGrid::create(vdb::Vec3s(0.0f));
    grid->setName("Cd");
    auto acc = grid->getAccessor();
    for (int z = 0; z < 12; ++z)
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 12; ++x) {
                glm::vec3 c = slabColour(x / 2);
                acc.setValueOn(vdb::Coord(x, y, z), vdb::Vec3s(c.x, c.y, c.z));
            }
    write(path, {grid});
}

void writeLevelSetWithColour(const fs::path& path) {
    vdb::initialize();
    auto surface =
        vdb::tools::createLevelSetSphere<vdb::FloatGrid>(10.0f, vdb::Vec3f(0.0f), 1.0f, 3.0f);
    surface->setName("surface");
    auto colour = vdb::Vec3SGrid::create(vdb::Vec3s(0.0f));
    colour->setName("Cd");
    auto acc = colour->getAccessor();
    for (int z = -12; z < 12; ++z)
        for (int y = -12; y < 12; ++y)
            for (int x = -12; x < 12; ++x)
                acc.setValueOn(vdb::Coord(x, y, z),
                               x < 0 ? vdb::Vec3s(0.8f, 0.1f, 0.1f) : vdb::Vec3s(0.1f, 0.1f, 0.8f));
    write(path, {surface, colour});
}

void writeZUpTower(const fs::path& path, const std::string& creator) {
    auto grid = vdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setGridClass(vdb::GRID_FOG_VOLUME);
    grid->tree().fill(vdb::CoordBBox(vdb::Coord(0, 0, 0), vdb::Coord(3, 3, 31)), 1.0f, true);
    grid->tree().fill(vdb::CoordBBox(vdb::Coord(-4, -4, 30), vdb::Coord(7, 7, 31)), 1.0f, true);
    vdb::MetaMap meta;
    if (!creator.empty()) meta.insertMeta("creator", vdb::StringMetadata(creator));
    write(path, {grid}, meta);
}

void writeMantaflowTower(const fs::path& path, bool gridMetadata) {
    auto density = vdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setGridClass(vdb::GRID_FOG_VOLUME);
    density->tree().fill(vdb::CoordBBox(vdb::Coord(0, 0, 0), vdb::Coord(3, 3, 31)), 1.0f, true);
    density->tree().fill(vdb::CoordBBox(vdb::Coord(-4, -4, 30), vdb::Coord(7, 7, 31)), 1.0f, true);
    vdb::GridPtrVec grids{density};
    if (gridMetadata) {
        density->insertMeta("file_base_resolution", vdb::Vec3IMetadata(vdb::Vec3i(12, 12, 32)));
        density->insertMeta("file_voxel_size", vdb::FloatMetadata(1.0f));
    } else {
        auto shadow = vdb::FloatGrid::create(0.0f);
        shadow->setName("shadow");
        grids.push_back(shadow);
    }
    write(path, grids);
}

void writeGridInstances(const fs::path& path) {
    auto grid = vdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->tree().fill(vdb::CoordBBox(vdb::Coord(0, 0, 0), vdb::Coord(29, 29, 0)), 1.0f, true);
    vdb::GridBase::Ptr copy = grid->copyGrid();  // shares the tree
    copy->setName("density_copy");
    write(path, {grid, copy});
}

void writeDuplicateNames(const fs::path& path) {
    vdb::GridPtrVec grids;
    for (int n : {2, 3}) {
        auto grid = vdb::FloatGrid::create(0.0f);
        grid->setName("density");
        grid->tree().fill(vdb::CoordBBox(vdb::Coord(0), vdb::Coord(n - 1)), 1.0f, true);
        grids.push_back(grid);
    }
    write(path, grids);
}

void writeFogCube(const fs::path& path, int n) {
    auto grid = vdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setGridClass(vdb::GRID_FOG_VOLUME);
    grid->tree().sparseFill(vdb::CoordBBox(vdb::Coord(0), vdb::Coord(n - 1)), 1.0f, true);
    write(path, {grid});
}

void writeMaskCube(const fs::path& path, int n) {
    auto grid = vdb::MaskGrid::create(false);
    grid->setName("mask");
    grid->tree().sparseFill(vdb::CoordBBox(vdb::Coord(0), vdb::Coord(n - 1)), true, true);
    write(path, {grid});
}

void writeIdGrid(const fs::path& path) {
    auto grid = vdb::Int32Grid::create(0);
    grid->setName("labels");
    grid->tree().fill(vdb::CoordBBox(vdb::Coord(0), vdb::Coord(7)), 7, true);
    grid->tree().fill(vdb::CoordBBox(vdb::Coord(8, 0, 0), vdb::Coord(15, 7, 7)), 42, true);
    grid->tree().setValueOn(vdb::Coord(20, 0, 0), -3);
    write(path, {grid});
}

void writeWrongTypes(const fs::path& path) {
    auto flow = vdb::Vec3IGrid::create(vdb::Vec3i(0));
    flow->setName("flow");
    flow->tree().setValueOn(vdb::Coord(1, 2, 3), vdb::Vec3i(1, 2, 3));
    auto empty = vdb::FloatGrid::create(0.0f);
    empty->setName("density");
    write(path, {flow, empty});
}

void writeEmptyGrid(const fs::path& path) {
    auto empty = vdb::FloatGrid::create(0.0f);
    empty->setName("density");
    write(path, {empty});
}

void writeRotatedGrid(const fs::path& path) {
    auto grid = fogBox(glm::ivec3(0), glm::ivec3(8));
    auto xf = vdb::math::Transform::createLinearTransform(1.0);
    xf->preRotate(30.0 * std::numbers::pi / 180.0, vdb::math::Y_AXIS);
    grid->setTransform(xf);
    write(path, {grid});
}

void writeFrustumGrid(const fs::path& path) {
    auto grid = fogBox(glm::ivec3(0), glm::ivec3(8));
    grid->setTransform(vdb::math::Transform::createFrustumTransform(
        vdb::BBoxd(vdb::Vec3d(0.0), vdb::Vec3d(16.0)), /*taper=*/0.5, /*depth=*/10.0,
        /*voxelDim=*/1.0));
    write(path, {grid});
}

void writeNonUniformGrid(const fs::path& path) {
    auto grid = fogBox(glm::ivec3(0), glm::ivec3(20));
    auto xf = vdb::math::Transform::createLinearTransform(1.0);
    xf->preScale(vdb::Vec3d(0.5, 0.5, 1.0));
    grid->setTransform(xf);
    write(path, {grid});
}

void writeGiantTile(const fs::path& path) {
    auto grid = vdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->tree().root().addTile(vdb::Coord(0), 1.0f, true);
    write(path, {grid});
}

void writeSeedCorpus(const fs::path& dir) {
    fs::create_directories(dir);
    writeLevelSetSphere(dir / "sphere.vdb", 6.0f, glm::vec3(1.0f, -2.0f, 3.0f));
    writeFogBox(dir / "fog_box.vdb", glm::ivec3(-3, 0, 2), glm::ivec3(9, 5, 13));
    writeColourGradient(dir / "gradient.vdb", 5);
    writeColourSlabs(dir / "slabs.vdb");
    writeLevelSetWithColour(dir / "sphere_cd.vdb");
    writeZUpTower(dir / "tower_blender.vdb", "Blender/Smoke");
    writeIdGrid(dir / "ids.vdb");
    writeGridInstances(dir / "instances.vdb");
    writeDuplicateNames(dir / "duplicate_names.vdb");
    writeMantaflowTower(dir / "tower_mantaflow.vdb", true);
    writeWrongTypes(dir / "wrong_types.vdb");
    writeEmptyGrid(dir / "empty_grid.vdb");
    writeRotatedGrid(dir / "rotated.vdb");
    writeFrustumGrid(dir / "frustum.vdb");
    writeNonUniformGrid(dir / "non_uniform.vdb");
    writeGiantTile(dir / "giant_tile.vdb");
    // Other compressions exercise the other decoders.
    {
        auto grid = fogBox(glm::ivec3(0), glm::ivec3(10));
        write(dir / "fog_zip.vdb", {grid}, vdb::MetaMap(),
              vdb::io::COMPRESS_ZIP | vdb::io::COMPRESS_ACTIVE_MASK);
        write(dir / "fog_raw.vdb", {grid}, vdb::MetaMap(), vdb::io::COMPRESS_NONE);
    }
    // A small voxengine world: a floor, a sphere, an emissive block, two materials and a camera.
    engine::world::Scene scene;
    scene.name = "seed";
    scene.grid = engine::world::BrickGrid(glm::ivec3(24, 16, 24));
    auto stone = *scene.palette.add({"stone", glm::vec3(0.5f), glm::vec3(0.0f), 0.0f});
    auto lamp = *scene.palette.add({"lamp", glm::vec3(0.9f), glm::vec3(1.0f, 0.8f, 0.5f), 4.0f});
    engine::world::fillBox(scene.grid, {glm::ivec3(0), glm::ivec3(24, 8, 24)}, stone);
    engine::world::fillSphere(scene.grid, glm::vec3(12.0f, 11.0f, 12.0f), 4.0f, lamp);
    scene.cameras.push_back({"front", glm::vec3(12, 10, -20), glm::vec3(12, 6, 12), 50.0f});
    engine::Status s = engine::io::exportVdb(scene, dir / "voxengine_world.vdb");
    (void)s;
}

}  // namespace vox::samples
