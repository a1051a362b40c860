// Reading scene and path files (TOML): a table reader that insists every key was understood
// (catches typos) and fails with "file:line: what". Failures are thrown as ParseError inside a
// parse and become a returned Error at its edge (parseToml); nothing throws past this layer.
#pragma once

#include <filesystem>
#include <fmt/format.h>
#include <functional>
#include <glm/glm.hpp>
#include <set>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

#include "core/error.h"
#include "core/number_check.h"
#include "core/quoted_string.h"

namespace engine::scene {

struct ParseError {
    std::string message;
};

// "file:line" of `at`, or just the file when there is no node (or no line) to point at.
std::string where(std::string_view source, const toml::node* at);

template <typename... Args>
[[noreturn]] void fail(std::string_view source, const toml::node* at, fmt::format_string<Args...> f,
                       Args&&... args) {
    throw ParseError{where(source, at) + ": " + fmt::format(f, std::forward<Args>(args)...)};
}

// Parses `text` as TOML and hands the root to `read`; TOML syntax errors and ParseErrors come
// back as "source:line: what".
template <typename T>
Result<T> parseToml(std::string_view text, std::string_view source,
                    const std::function<T(const toml::table&)>& read) {
    try {
        toml::table root = toml::parse(text, source);
        return read(root);
    } catch (const toml::parse_error& e) {
        return makeError("{}:{}: {}", source, e.source().begin.line,
                         printableText(e.description()));
    } catch (const ParseError& e) {
        return Error{e.message};
    }
}

// The whole file as text; `what` names the kind of file in the message ("scene file").
Result<std::string> readTextFile(const std::filesystem::path& path, std::string_view what);

// Reads one table and, when it goes out of scope without an error in flight, fails on the first
// key nobody asked for.
class KeyReader {
public:
    KeyReader(std::string_view source, const toml::table& t) : mSource(source), mTable(t) {}
    ~KeyReader() noexcept(false);
    KeyReader(const KeyReader&) = delete;
    KeyReader& operator=(const KeyReader&) = delete;

    template <typename... Args>
    [[noreturn]] void fail(const toml::node* at, fmt::format_string<Args...> f,
                           Args&&... args) const {
        scene::fail(mSource, at, f, std::forward<Args>(args)...);
    }
    std::string where(const toml::node* at) const { return scene::where(mSource, at); }
    std::string_view source() const { return mSource; }

    const toml::node* node(std::string_view key);  // marks the key understood
    const toml::table& raw() const { return mTable; }
    bool has(std::string_view key) const { return mTable.contains(key); }
    // Marks every key understood (a table whose other keys belong to someone else).
    void acceptAll();
    // Fails now on the first key nobody asked for; the destructor then checks nothing. Call it
    // before returning a value built while this reader lives: a destructor that throws after the
    // return value is made can leak that value (clang 14 does; the scene fuzzer found it).
    void finish();

    // Each returns `fallback` when the key is absent, unless `required` (then "missing 'key'").
    // Every number is checked against its range (core/number_check.h): a key cannot be read
    // without stating what it accepts, so NaN, infinities and out-of-range values never pass.
    double number(std::string_view key, double fallback, const NumberRange& range,
                  bool required = false);
    int integer(std::string_view key, int fallback, const NumberRange& range);
    bool boolean(std::string_view key, bool fallback, bool required = false);
    // Strings are names, types and paths: printable text, one line (core/quoted_string.h), so
    // whatever shows them later -- a message, a report, the HUD -- shows what the file says.
    std::string string(std::string_view key,
                       const char* fallback = nullptr);      // no fallback: required
    std::vector<std::string> strings(std::string_view key);  // an array of strings; absent: none
    // Vectors: `range` holds for each component.
    glm::vec2 vec2(std::string_view key, glm::vec2 fallback, const NumberRange& range,
                   bool required = false);
    glm::vec3 vec3(std::string_view key, glm::vec3 fallback, const NumberRange& range,
                   bool required = false);
    glm::ivec2 ivec2(std::string_view key, glm::ivec2 fallback, const NumberRange& range,
                     bool required = false);
    glm::ivec3 ivec3(std::string_view key, glm::ivec3 fallback, const NumberRange& range,
                     bool required = false);

private:
    template <int N>
    glm::vec<N, double> vector(std::string_view key, glm::vec<N, double> fallback,
                               NumberRange range, bool required);
    void check(const toml::node* at, std::string_view name, double value, const NumberRange& range);
    const std::string& printable(const toml::node* at, std::string_view key,
                                 const std::string& text) const;

    std::string mSource;
    const toml::table& mTable;
    std::set<std::string> mUsed;
    bool mFinished = false;
};

// Ranges many keys share.
// Voxel indices (box corners, offsets): the largest world is 32768 voxels across.
inline constexpr NumberRange kVoxelIndexRange = wholeRange(-(1 << 20), 1 << 20, "voxels");
inline constexpr NumberRange kSeedRange = wholeRange(0, 2147483647);

}  // namespace engine::scene
