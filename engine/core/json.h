// JSON values, read and written: the job manifests of tools/vox (job_manifest.h) are JSON so that
// people and tools (jq, Python) read them as easily as vox does. Objects keep their keys in the
// order they were added, so a file reads back and is written again unchanged. Numbers are doubles
// (integers exact up to 2^53), written in the shortest form that reads back to the same double;
// NaN and infinities are written as null.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"

namespace engine {

class Json {
public:
    enum class Type { Null, Bool, Number, String, Array, Object };

    Json() = default;  // null
    Json(bool value) : mType(Type::Bool), mBool(value) {}
    Json(double value) : mType(Type::Number), mNumber(value) {}
    Json(int value) : Json(double(value)) {}
    Json(unsigned value) : Json(double(value)) {}
    Json(std::int64_t value) : Json(double(value)) {}
    Json(std::uint64_t value) : Json(double(value)) {}
    Json(std::string value) : mType(Type::String), mString(std::move(value)) {}
    Json(std::string_view value) : Json(std::string(value)) {}
    Json(const char* value) : Json(std::string(value)) {}
    static Json array() { return Json(Type::Array); }
    static Json object() { return Json(Type::Object); }

    Type type() const { return mType; }
    bool isNull() const { return mType == Type::Null; }
    bool isNumber() const { return mType == Type::Number; }
    bool isString() const { return mType == Type::String; }
    bool isArray() const { return mType == Type::Array; }
    bool isObject() const { return mType == Type::Object; }

    // The value, or `fallback` when it is of another type (a missing member reads as null).
    bool boolean(bool fallback = false) const { return mType == Type::Bool ? mBool : fallback; }
    double number(double fallback = 0.0) const {
        return mType == Type::Number ? mNumber : fallback;
    }
    const std::string& string() const;  // empty unless a string

    // Arrays: the items (empty for any other type); push turns null into an array.
    const std::vector<Json>& items() const;
    std::vector<Json>& items();
    void push(Json value);

    // Objects: members in insertion order. get() returns a null value when the key is missing;
    // operator[] adds the key (as null) when missing, turning null into an object.
    const std::vector<std::pair<std::string, Json>>& members() const;
    const Json* find(std::string_view key) const;
    const Json& get(std::string_view key) const;
    Json& operator[](std::string_view key);
    bool erase(std::string_view key);

    // Text with two-space indentation; containers nested deeper than `expandDepth` levels are
    // written on one line (a manifest's records stay one line each).
    std::string dump(int expandDepth = 2) const;

    bool operator==(const Json& other) const;

private:
    explicit Json(Type type) : mType(type) {}
    void dumpTo(std::string& out, int depth, int expandDepth) const;

    Type mType = Type::Null;
    bool mBool = false;
    double mNumber = 0.0;
    std::string mString;
    std::vector<Json> mItems;
    std::vector<std::pair<std::string, Json>> mMembers;
};

// Parses one JSON document (RFC 8259). An error names `source`, line and column:
// "out/cap/job.json:3:14: expected ',' or '}'".
Result<Json> parseJson(std::string_view text, std::string_view source);

}  // namespace engine
