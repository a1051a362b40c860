// The writer of scene/toml_writer.h.
#include "scene/toml_writer.h"

#include <fmt/format.h>

#include "core/quoted_string.h"

namespace engine::scene {

namespace {

// fmt's "{}" is the shortest text that reads back as the same value; TOML floats need a '.' or
// an exponent ("2" would read back as an integer), and spell infinity and NaN its own way.
std::string withPoint(std::string s) {
    if (s == "inf" || s == "-inf" || s == "nan" || s == "-nan") return s;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
}

}  // namespace

std::string tomlNumber(float f) { return withPoint(fmt::format("{}", f)); }
std::string tomlNumber(double d) { return withPoint(fmt::format("{}", d)); }

void TomlWriter::comment(std::string_view text) {
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        mText += fmt::format("# {}\n", text.substr(start, end - start));
        start = end + 1;
    }
}

void TomlWriter::table(std::string_view name) {
    if (!mText.empty()) mText += '\n';
    mText += fmt::format("[{}]\n", name);
}

void TomlWriter::arrayTable(std::string_view name) {
    if (!mText.empty()) mText += '\n';
    mText += fmt::format("[[{}]]\n", name);
}

void TomlWriter::raw(std::string_view name, std::string_view value) {
    mText += fmt::format("{} = {}\n", name, value);
}

void TomlWriter::key(std::string_view name, std::string_view text) {
    raw(name, quotedString(text));
}
void TomlWriter::key(std::string_view name, bool value) { raw(name, value ? "true" : "false"); }
void TomlWriter::key(std::string_view name, int value) { raw(name, fmt::format("{}", value)); }
void TomlWriter::key(std::string_view name, std::uint32_t value) {
    raw(name, fmt::format("{}", value));
}
void TomlWriter::key(std::string_view name, float value) { raw(name, tomlNumber(value)); }
void TomlWriter::key(std::string_view name, double value) { raw(name, tomlNumber(value)); }
void TomlWriter::key(std::string_view name, glm::vec2 v) {
    raw(name, fmt::format("[{}, {}]", tomlNumber(v.x), tomlNumber(v.y)));
}
void TomlWriter::key(std::string_view name, glm::vec3 v) {
    raw(name, fmt::format("[{}, {}, {}]", tomlNumber(v.x), tomlNumber(v.y), tomlNumber(v.z)));
}
void TomlWriter::key(std::string_view name, glm::dvec3 v) {
    raw(name, fmt::format("[{}, {}, {}]", tomlNumber(v.x), tomlNumber(v.y), tomlNumber(v.z)));
}
void TomlWriter::key(std::string_view name, glm::ivec2 v) {
    raw(name, fmt::format("[{}, {}]", v.x, v.y));
}
void TomlWriter::key(std::string_view name, glm::ivec3 v) {
    raw(name, fmt::format("[{}, {}, {}]", v.x, v.y, v.z));
}
void TomlWriter::key(std::string_view name, const std::vector<std::string>& texts) {
    std::string list;
    for (const std::string& t : texts) list += (list.empty() ? "" : ", ") + quotedString(t);
    raw(name, "[" + list + "]");
}

}  // namespace engine::scene
