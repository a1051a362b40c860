#include "io/vdb_layout.h"

#include <fmt/format.h>

#include "core/number_check.h"
#include "core/quoted_string.h"
#include "world/world_limits.h"

namespace engine::io::vdb_layout {

namespace vdb = openvdb;

namespace {

vdb::Vec3s toVdb(glm::vec3 v) { return {v.x, v.y, v.z}; }
glm::vec3 fromVdb(const vdb::Vec3s& v) { return {v.x(), v.y(), v.z()}; }

std::string materialKey(std::size_t i, const char* field) {
    return fmt::format("vox:material.{:05}.{}", i, field);
}
std::string cameraKey(std::size_t i, const char* field) {
    return fmt::format("vox:camera.{:03}.{}", i, field);
}

// Typed lookups that report the key instead of throwing; numbers checked by the range the scene
// file's key has (world/scene.h), so a file cannot give the world what a scene file may not.
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
            mError =
                fmt::format("{}: voxengine metadata '{}' has type {}, expected {}", mFile, key,
                            printableText(m->typeName()), vdb::TypedMetadata<T>::staticTypeName());
            return false;
        }
        out = typed->value();
        return true;
    }
    // A name: printable text, as a scene file's strings are (scene/toml_reader.h).
    bool text(const std::string& key, std::string& out) {
        if (!get(key, out)) return false;
        if (printableText(out) == out) return true;
        return fail(fmt::format(
            "voxengine metadata '{}' must be printable text, without control characters: '{}'", key,
            printableText(out)));
    }
    bool number(const std::string& key, float& out, const NumberRange& range) {
        return get(key, out) && check(key, out, range);
    }
    bool vec3(const std::string& key, glm::vec3& out, const NumberRange& range) {
        vdb::Vec3s v(0.0f);
        if (!get(key, v)) return false;
        out = fromVdb(v);
        for (int i = 0; i < 3; ++i)
            if (!check(fmt::format("{} {}", key, "xyz"[i]), out[i], range)) return false;
        return true;
    }
    bool check(std::string_view name, double value, const NumberRange& range) {
        if (!mError.empty()) return false;
        if (Status ok = checkNumber(name, value, range); !ok) return fail(ok.error().message);
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

}  // namespace

vdb::math::Transform::Ptr gridTransform(double voxelSize, bool zUp) {
    vdb::math::Transform::Ptr xform = vdb::math::Transform::createLinearTransform(voxelSize);
    if (zUp) {
        // OpenVDB's matrices act on row vectors, so this is the turn that takes +y to +z.
        vdb::Mat4d turn(1, 0, 0, 0,   //
                        0, 0, 1, 0,   //
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
        r.fail(fmt::format("voxengine format version {} is newer than this build reads ({})",
                           version, kFormatVersion));
    r.text("vox:world.name", h.name);
    r.get("vox:world.size", size);
    r.number("vox:world.voxel_size", h.voxelSize, world::kVoxelSizeRange);
    if (auto up = vdb::DynamicPtrCast<const vdb::StringMetadata>(meta["vox:up_axis"]))
        h.zUp = up->value() == "z";
    h.size = glm::ivec3(size.x(), size.y(), size.z());
    if (r.error().empty()) {
        glm::u64vec3 cells = glm::u64vec3((glm::max(h.size, 1) + 7) / 8);
        if (glm::any(glm::lessThan(h.size, glm::ivec3(1))) ||
            glm::any(glm::greaterThan(h.size, glm::ivec3(world::kMaxWorldExtent))) ||
            cells.x * cells.y * cells.z > world::kMaxTopGridCells)
            r.fail(fmt::format("vox:world.size {}x{}x{} is outside the engine's limits", h.size.x,
                               h.size.y, h.size.z));
    }
    r.get("vox:palette.count", paletteCount);
    if (r.error().empty() &&
        (paletteCount < 0 || std::size_t(paletteCount) >= world::kMaxMaterials))
        r.fail(fmt::format("vox:palette.count {} is outside 0..{}", paletteCount,
                           world::kMaxMaterials - 1));
    for (std::int32_t i = 1; r.error().empty() && i <= paletteCount; ++i) {
        world::Material m;
        r.text(materialKey(std::size_t(i), "name"), m.name);
        r.vec3(materialKey(std::size_t(i), "albedo"), m.albedo, world::kAlbedoRange);
        r.vec3(materialKey(std::size_t(i), "emission"), m.emissionColor, world::kRadianceRange);
        r.number(materialKey(std::size_t(i), "strength"), m.emissionStrength,
                 world::kRadianceRange);
        if (r.error().empty()) (void)h.palette.add(m);
    }
    r.get("vox:camera.count", cameraCount);
    if (r.error().empty() && (cameraCount < 0 || cameraCount > 1000))
        r.fail(fmt::format("vox:camera.count {} is outside 0..1000", cameraCount));
    for (std::int32_t i = 0; r.error().empty() && i < cameraCount; ++i) {
        world::CameraPreset c;
        r.text(cameraKey(std::size_t(i), "name"), c.name);
        r.vec3(cameraKey(std::size_t(i), "position"), c.position, world::kCoordinateRange);
        r.vec3(cameraKey(std::size_t(i), "target"), c.target, world::kCoordinateRange);
        r.number(cameraKey(std::size_t(i), "fov"), c.fovYDegrees, world::kFovRange);
        if (r.error().empty())
            if (Status ok = world::checkCamera(c); !ok)
                r.fail(
                    fmt::format("{}: {}", cameraKey(std::size_t(i), "target"), ok.error().message));
        h.cameras.push_back(c);
    }
    r.vec3("vox:sky.sun_direction", h.sky.sunDirection, world::kDirectionRange);
    if (r.error().empty() && glm::length(h.sky.sunDirection) < 1e-6f)
        r.fail("vox:sky.sun_direction must not be zero");
    r.vec3("vox:sky.sun_radiance", h.sky.sunRadiance, world::kRadianceRange);
    r.vec3("vox:sky.sky_radiance", h.sky.skyRadiance, world::kRadianceRange);
    if (!r.error().empty()) return Error{r.error()};
    return h;
}

}  // namespace engine::io::vdb_layout
