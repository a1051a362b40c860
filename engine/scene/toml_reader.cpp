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
    if (mFinished || std::uncaught_exceptions()) return;
    finish();
}

void KeyReader::finish() {
    mFinished = true;
    for (auto&& [key, node] : mTable) {
        if (!mUsed.count(std::string(key.str())))
            fail(&node, "unknown key '{}'", printableText(key.str()));
    }
}

const toml::node* KeyReader::node(std::string_view key) {
    mUsed.insert(std::string(key));
    return mTable.get(key);
}

void KeyReader::acceptAll() {
    for (auto&& [key, node] : mTable) mUsed.insert(std::string(key.str()));
}

const std::string& KeyReader::printable(const toml::node* at, std::string_view key,
                                        const std::string& text) const {
    if (printableText(text) != text)
        fail(at, "'{}' must be printable text, without control characters: '{}'", key,
             printableText(text));
    return text;
}

void KeyReader::check(const toml::node* at, std::string_view name, double value,
                      const NumberRange& range) {
    if (Status ok = checkNumber(name, value, range); !ok) fail(at, "{}", ok.error().message);
}

double KeyReader::number(std::string_view key, double fallback, const NumberRange& range,
                         bool required) {
    const toml::node* n = node(key);
    if (!n) {
        if (required) fail(&mTable, "missing '{}'", key);
        return fallback;
    }
    auto v = n->value<double>();
    if (!v) fail(n, "'{}' must be a number in {}", key, describeRange(range));
    check(n, fmt::format("'{}'", key), *v, range);
    return *v;
}

int KeyReader::integer(std::string_view key, int fallback, const NumberRange& range) {
    const toml::node* n = node(key);
    if (!n) return fallback;
    NumberRange whole = range;
    whole.whole = true;
    if (auto v = n->value_exact<std::int64_t>()) {
        check(n, fmt::format("'{}'", key), static_cast<double>(*v), whole);
        return static_cast<int>(*v);
    }
    // A float (3.0, 1e300, nan): refused, with the range it should have been in.
    if (auto v = n->value<double>()) check(n, fmt::format("'{}'", key), *v, whole);
    fail(n, "'{}' must be a whole number in {}", key, describeRange(whole));
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
    if (auto v = n->value<std::string>()) return printable(n, key, *v);
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
        out.push_back(printable(&e, key, *v));
    }
    return out;
}

template <int N>
glm::vec<N, double> KeyReader::vector(std::string_view key, glm::vec<N, double> fallback,
                                      NumberRange range, bool required) {
    const toml::node* n = node(key);
    if (!n) {
        if (required) fail(&mTable, "missing '{}'", key);
        return fallback;
    }
    const toml::array* a = n->as_array();
    const char* kind = range.whole ? "whole numbers" : "numbers";
    if (!a || a->size() != N) fail(n, "'{}' must be an array of {} {}", key, N, kind);
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) {
        const toml::node& e = (*a)[std::size_t(i)];
        auto v = e.value<double>();
        if (!v) fail(n, "'{}' must be an array of {} {}", key, N, kind);
        check(n, fmt::format("'{}' {}", key, "xyzw"[i]), *v, range);
        out[i] = *v;
    }
    return out;
}

glm::vec2 KeyReader::vec2(std::string_view key, glm::vec2 fallback, const NumberRange& range,
                          bool required) {
    return glm::vec2(vector<2>(key, glm::dvec2(fallback), range, required));
}
glm::vec3 KeyReader::vec3(std::string_view key, glm::vec3 fallback, const NumberRange& range,
                          bool required) {
    return glm::vec3(vector<3>(key, glm::dvec3(fallback), range, required));
}
glm::ivec2 KeyReader::ivec2(std::string_view key, glm::ivec2 fallback, const NumberRange& range,
                            bool required) {
    NumberRange whole = range;
    whole.whole = true;
    return glm::ivec2(vector<2>(key, glm::dvec2(fallback), whole, required));
}
glm::ivec3 KeyReader::ivec3(std::string_view key, glm::ivec3 fallback, const NumberRange& range,
                            bool required) {
    NumberRange whole = range;
    whole.whole = true;
    return glm::ivec3(vector<3>(key, glm::dvec3(fallback), whole, required));
}

}  // namespace engine::scene
