#include "world/scene_file_writer.h"

#include <fmt/format.h>

namespace engine::world {

namespace {

// fmt's "{}" is the shortest text that reads back as the same float.
std::string number(float f) {
    std::string s = fmt::format("{}", f);
    // TOML floats need a '.' or an exponent; "2" would read back as an integer.
    if (s.find_first_of(".eE") == std::string::npos && s.find_first_of("in") == std::string::npos) s += ".0";
    return s;
}
std::string vec3f(glm::vec3 v) { return fmt::format("[{}, {}, {}]", number(v.x), number(v.y), number(v.z)); }

}  // namespace

std::string tomlString(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            case '\r': out += "\\r"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                    out += fmt::format("\\u{:04X}", static_cast<unsigned char>(c));
                else
                    out += c;
        }
    }
    return out + "\"";
}

std::string sceneTextWithPalette(const Scene& scene, std::string_view generators, std::string_view headerComment) {
    std::string out;
    if (!headerComment.empty()) out += fmt::format("# {}\n", headerComment);
    glm::ivec3 size = scene.grid.sizeInVoxels();
    out += fmt::format("[world]\nname = {}\nsize = [{}, {}, {}]\nvoxel_size = {}\n", tomlString(scene.name), size.x, size.y,
                       size.z, number(scene.voxelSize));
    const auto& materials = scene.palette.materials();
    for (std::size_t i = 1; i < materials.size(); ++i) {
        const Material& m = materials[i];
        out += fmt::format("\n[[material]]\nname = {}\nalbedo = {}\n", tomlString(m.name), vec3f(m.albedo));
        if (m.emissive())
            out += fmt::format("emission = {}\nstrength = {}\n", vec3f(m.emissionColor), number(m.emissionStrength));
    }
    if (!generators.empty()) out += fmt::format("\n{}", generators);
    for (const CameraPreset& c : scene.cameras) {
        out += fmt::format("\n[[camera]]\nname = {}\nposition = {}\ntarget = {}\nfov = {}\n", tomlString(c.name),
                           vec3f(c.position), vec3f(c.target), number(c.fovYDegrees));
    }
    out += fmt::format("\n[sky]\nsun_direction = {}\nsun_radiance = {}\nsky_radiance = {}\n", vec3f(scene.sky.sunDirection),
                       vec3f(scene.sky.sunRadiance), vec3f(scene.sky.skyRadiance));
    return out;
}

}  // namespace engine::world
