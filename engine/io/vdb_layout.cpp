#include "io/vdb_layout.h"

#include <fmt/format.h>

#include "world/world_limits.h"

namespace engine::io::vdb_layout {

namespace vdb = openvdb;

namespace {

vdb::Vec3s toVdb(glm::vec3 v) { return {v.x, v.y, v.z}; }
glm::vec3 fromVdb(const vdb::Vec3s& v) { return {v.x(), v.y(), v.z()}; }

std::string materialKey(std::size_t i, const char* field) { return fmt::format("vox:material.{:05}.{}", i, field); }
std::string cameraKey(std::size_t i, const char* field) { return fmt::format("vox:camera.{:03}.{}", i, field); }

// Typed lookups that report the key instead of throwing.
class Reader {
public:
    Reader(const vdb::MetaMap& meta, const std::string& file) : mMeta(meta), mFile(file) {}

    template <typename T>
    bool get(const std::string& key, T& out) {
        if (!mError.empty()) return false;
        vdb::Metadata::ConstPtr m = mMeta[key];
        if (!m) {
            mError = fmt::format("{}: voxengine metadata '{}' is missing", mFile, key);
            return false;
        }
        auto typed = vdb::DynamicPtrCast<const vdb::TypedMetadata<T>>(m);
        if (!typed) {
            mError = fmt::format("{}: voxengine metadata '{}' has type {}, expected {}", mFile, key, m->typeName(),
                                 vdb::TypedMetadata<T>::staticTypeName());
            return false;
        }
        out = typed->value();
        return true;
    }
    bool vec3(const std::string& key, glm::vec3& out) {
        vdb::Vec3s v(0.0f);
        if (!get(key, v)) return false;
        out = fromVdb(v);
        return true;
    }
    bool fail(std::string message) {
        if (mError.empty()) mError = fmt::format("{}: {}", mFile, message);
        return false;
    }
    const std::string& error() const { return mError; }

private:
    const vdb::MetaMap& mMeta;
    std::string mFile;
    std::string mError;
};

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

vdb::math::Transform::Ptr gridTransform(double voxelSize, bool zUp) {
    vdb::math::Transform::Ptr xform = vdb::math::Transform::createLinearTransform(voxelSize);
    if (zUp) {
        // OpenVDB's matrices act on row vectors, so this is the turn that takes +y to +z.
        vdb::Mat4d turn(1, 0, 0, 0,  //
                        0, 0, 1, 0,  //
                        0, -1, 0, 0,  //
                        0, 0, 0, 1);
        xform->postMult(turn);
    }
    return xform;
}

void writeWorldMetadata(const world::Scene& scene, vdb::MetaMap& out, bool zUp) {
    out.insertMeta(kFormatKey, vdb::StringMetadata(kFormatName));
    out.insertMeta("vox:format_version", vdb::Int32Metadata(kFormatVersion));
    out.insertMeta("vox:up_axis", vdb::StringMetadata(zUp ? "z" : "y"));
    out.insertMeta("vox:world.name", vdb::StringMetadata(scene.name));
    glm::ivec3 size = scene.grid.sizeInVoxels();
    out.insertMeta("vox:world.size", vdb::Vec3IMetadata(vdb::Vec3i(size.x, size.y, size.z)));
    out.insertMeta("vox:world.voxel_size", vdb::FloatMetadata(scene.voxelSize));
    const auto& materials = scene.palette.materials();
    out.insertMeta("vox:palette.count", vdb::Int32Metadata(std::int32_t(materials.size() - 1)));
    for (std::size_t i = 1; i < materials.size(); ++i) {
        const world::Material& m = materials[i];
        out.insertMeta(materialKey(i, "name"), vdb::StringMetadata(m.name));
        out.insertMeta(materialKey(i, "albedo"), vdb::Vec3SMetadata(toVdb(m.albedo)));
        out.insertMeta(materialKey(i, "emission"), vdb::Vec3SMetadata(toVdb(m.emissionColor)));
        out.insertMeta(materialKey(i, "strength"), vdb::FloatMetadata(m.emissionStrength));
    }
    out.insertMeta("vox:camera.count", vdb::Int32Metadata(std::int32_t(scene.cameras.size())));
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const world::CameraPreset& c = scene.cameras[i];
        out.insertMeta(cameraKey(i, "name"), vdb::StringMetadata(c.name));
        out.insertMeta(cameraKey(i, "position"), vdb::Vec3SMetadata(toVdb(c.position)));
        out.insertMeta(cameraKey(i, "target"), vdb::Vec3SMetadata(toVdb(c.target)));
        out.insertMeta(cameraKey(i, "fov"), vdb::FloatMetadata(c.fovYDegrees));
    }
    out.insertMeta("vox:sky.sun_direction", vdb::Vec3SMetadata(toVdb(scene.sky.sunDirection)));
    out.insertMeta("vox:sky.sun_radiance", vdb::Vec3SMetadata(toVdb(scene.sky.sunRadiance)));
    out.insertMeta("vox:sky.sky_radiance", vdb::Vec3SMetadata(toVdb(scene.sky.skyRadiance)));
}

bool isVoxengineFile(const vdb::MetaMap& meta) {
    vdb::Metadata::ConstPtr m = meta[kFormatKey];
    auto s = vdb::DynamicPtrCast<const vdb::StringMetadata>(m);
    return s && s->value() == kFormatName;
}

Result<WorldHeader> readWorldMetadata(const vdb::MetaMap& meta, const std::string& file) {
    Reader r(meta, file);
    WorldHeader h;
    std::int32_t version = 0, paletteCount = 0, cameraCount = 0;
    vdb::Vec3i size(0);
    r.get("vox:format_version", version);
    if (r.error().empty() && version > kFormatVersion)
        r.fail(fmt::format("voxengine format version {} is newer than this build reads ({})", version, kFormatVersion));
    r.get("vox:world.name", h.name);
    r.get("vox:world.size", size);
    r.get("vox:world.voxel_size", h.voxelSize);
    if (auto up = vdb::DynamicPtrCast<const vdb::StringMetadata>(meta["vox:up_axis"])) h.zUp = up->value() == "z";
    h.size = glm::ivec3(size.x(), size.y(), size.z());
    if (r.error().empty()) {
        glm::u64vec3 cells = glm::u64vec3((glm::max(h.size, 1) + 7) / 8);
        if (glm::any(glm::lessThan(h.size, glm::ivec3(1))) ||
            glm::any(glm::greaterThan(h.size, glm::ivec3(world::kMaxWorldExtent))) ||
            cells.x * cells.y * cells.z > world::kMaxTopGridCells)
            r.fail(fmt::format("vox:world.size {}x{}x{} is outside the engine's limits", h.size.x, h.size.y, h.size.z));
        if (!(h.voxelSize > 0.0f && std::isfinite(h.voxelSize))) r.fail("vox:world.voxel_size must be positive");
    }
    r.get("vox:palette.count", paletteCount);
    if (r.error().empty() && (paletteCount < 0 || std::size_t(paletteCount) >= world::kMaxMaterials))
        r.fail(fmt::format("vox:palette.count {} is outside 0..{}", paletteCount, world::kMaxMaterials - 1));
    for (std::int32_t i = 1; r.error().empty() && i <= paletteCount; ++i) {
        world::Material m;
        r.get(materialKey(std::size_t(i), "name"), m.name);
        r.vec3(materialKey(std::size_t(i), "albedo"), m.albedo);
        r.vec3(materialKey(std::size_t(i), "emission"), m.emissionColor);
        r.get(materialKey(std::size_t(i), "strength"), m.emissionStrength);
        if (r.error().empty() && (!finite(m.albedo) || !finite(m.emissionColor) || !std::isfinite(m.emissionStrength)))
            r.fail(fmt::format("material {} has a value that is not a finite number", i));
        if (r.error().empty()) (void)h.palette.add(m);
    }
    r.get("vox:camera.count", cameraCount);
    if (r.error().empty() && (cameraCount < 0 || cameraCount > 1000))
        r.fail(fmt::format("vox:camera.count {} is outside 0..1000", cameraCount));
    for (std::int32_t i = 0; r.error().empty() && i < cameraCount; ++i) {
        world::CameraPreset c;
        r.get(cameraKey(std::size_t(i), "name"), c.name);
        r.vec3(cameraKey(std::size_t(i), "position"), c.position);
        r.vec3(cameraKey(std::size_t(i), "target"), c.target);
        r.get(cameraKey(std::size_t(i), "fov"), c.fovYDegrees);
        h.cameras.push_back(c);
    }
    r.vec3("vox:sky.sun_direction", h.sky.sunDirection);
    r.vec3("vox:sky.sun_radiance", h.sky.sunRadiance);
    r.vec3("vox:sky.sky_radiance", h.sky.skyRadiance);
    if (!r.error().empty()) return Error{r.error()};
    return h;
}

}  // namespace engine::io::vdb_layout
