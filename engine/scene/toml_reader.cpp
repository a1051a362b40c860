// The table reader of scene/toml_reader.h.
#include "scene/toml_reader.h"

#include <cmath>
#include <exception>
#include <fstream>
#include <sstream>

namespace engine::scene {

std::string where(std::string_view source, const toml::node* at) {
    if (at && at->source().begin.line) return fmt::format("{}:{}", source, at->source().begin.line);
    return std::string(source);
}

Result<std::string> readTextFile(const std::filesystem::path& path, std::string_view what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError("{}: cannot open {}", path.string(), what);
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return makeError("{}: read error", path.string());
    return text.str();
}

KeyReader::~KeyReader() noexcept(false) {
    if (std::uncaught_exceptions()) return;
    for (auto&& [key, node] : mTable) {
        if (!mUsed.count(std::string(key.str()))) fail(&node, "unknown key '{}'", key.str());
    }
}

const toml::node* KeyReader::node(std::string_view key) {
    mUsed.insert(std::string(key));
    return mTable.get(key);
}

void KeyReader::acceptAll() {
    for (auto&& [key, node] : mTable) mUsed.insert(std::string(key.str()));
}

double KeyReader::number(std::string_view key, double fallback, bool required) {
    const toml::node* n = node(key);
    if (!n) {
        if (required) fail(&mTable, "missing '{}'", key);
        return fallback;
    }
    if (auto v = n->value<double>(); v && std::isfinite(*v)) return *v;
    fail(n, "'{}' must be a number", key);
}

int KeyReader::integer(std::string_view key, int fallback) {
    const toml::node* n = node(key);
    if (!n) return fallback;
    if (auto v = n->value<std::int64_t>()) {
        if (*v < -(1ll << 30) || *v > (1ll << 30)) fail(n, "'{}' is out of range", key);
        return static_cast<int>(*v);
    }
    fail(n, "'{}' must be an integer", key);
}

bool KeyReader::boolean(std::string_view key, bool fallback, bool required) {
    const toml::node* n = node(key);
    if (!n) {
        if (required) fail(&mTable, "missing '{}'", key);
        return fallback;
    }
    if (auto v = n->value<bool>()) return *v;
    fail(n, "'{}' must be true or false", key);
}

std::string KeyReader::string(std::string_view key, const char* fallback) {
    const toml::node* n = node(key);
    if (!n) {
        if (!fallback) fail(&mTable, "missing '{}'", key);
        return fallback;
    }
    if (auto v = n->value<std::string>()) return *v;
    fail(n, "'{}' must be a string", key);
}

std::vector<std::string> KeyReader::strings(std::string_view key) {
    const toml::node* n = node(key);
    std::vector<std::string> out;
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(n, "'{}' must be an array of strings", key);
    for (const toml::node& e : *a) {
        auto v = e.value<std::string>();
        if (!v) fail(n, "'{}' must be an array of strings", key);
        out.push_back(*v);
    }
    return out;
}

template <int N>
glm::vec<N, double> KeyReader::vector(std::string_view key, glm::vec<N, double> fallback,
                                      bool required) {
    const toml::node* n = node(key);
    if (!n) {
        if (required) fail(&mTable, "missing '{}'", key);
        return fallback;
    }
    const toml::array* a = n->as_array();
    if (!a || a->size() != N) fail(n, "'{}' must be an array of {} numbers", key, N);
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) {
        auto v = (*a)[std::size_t(i)].value<double>();
        // Finite and at most 1e7: far beyond any world, and floats still hold whole voxels there.
        if (!v || !std::isfinite(*v) || std::abs(*v) > 1e7)
            fail(n, "'{}' must be an array of {} numbers", key, N);
        out[i] = *v;
    }
    return out;
}

template <int N>
glm::vec<N, int> KeyReader::whole(std::string_view key, glm::vec<N, int> fallback, bool required) {
    using V = glm::vec<N, double>;
    V v = vector<N>(key, V(fallback), required);
    if (glm::any(glm::notEqual(glm::floor(v), v)) ||
        glm::any(glm::greaterThan(glm::abs(v), V(1 << 20))))
        fail(node(key), "'{}' must hold whole numbers of voxels", key);
    return glm::vec<N, int>(v);
}

glm::vec2 KeyReader::vec2(std::string_view key, glm::vec2 fallback, bool required) {
    return glm::vec2(vector<2>(key, glm::dvec2(fallback), required));
}
glm::vec3 KeyReader::vec3(std::string_view key, glm::vec3 fallback, bool required) {
    return glm::vec3(vector<3>(key, glm::dvec3(fallback), required));
}
glm::ivec2 KeyReader::ivec2(std::string_view key, glm::ivec2 fallback, bool required) {
    return whole<2>(key, fallback, required);
}
glm::ivec3 KeyReader::ivec3(std::string_view key, glm::ivec3 fallback, bool required) {
    return whole<3>(key, fallback, required);
}

}  // namespace engine::scene
