// Writing scene and path files (TOML): tables and keys in the order given, floats in their
// shortest exact form (the text reads back as the very same float or double), strings through
// the one escaper (core/quoted_string.h).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace engine::scene {

std::string tomlNumber(float f);
std::string tomlNumber(double d);

class TomlWriter {
public:
    // "# line" for each line of `text`.
    void comment(std::string_view text);
    // "[name]" or "[[name]]", after a blank line unless it opens the file.
    void table(std::string_view name);
    void arrayTable(std::string_view name);

    void key(std::string_view name, std::string_view text);  // a string
    void key(std::string_view name, const char* text) { key(name, std::string_view(text)); }
    void key(std::string_view name, const std::string& text) { key(name, std::string_view(text)); }
    void key(std::string_view name, bool value);
    void key(std::string_view name, int value);
    void key(std::string_view name, std::uint32_t value);
    void key(std::string_view name, float value);
    void key(std::string_view name, double value);
    void key(std::string_view name, glm::vec2 value);
    void key(std::string_view name, glm::vec3 value);
    void key(std::string_view name, glm::dvec3 value);
    void key(std::string_view name, glm::ivec2 value);
    void key(std::string_view name, glm::ivec3 value);
    void key(std::string_view name, const std::vector<std::string>& texts);

    const std::string& text() const { return mText; }

private:
    void raw(std::string_view name, std::string_view value);
    std::string mText;
};

}  // namespace engine::scene
