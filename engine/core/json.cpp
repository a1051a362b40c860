// JSON reading and writing (core/json.h).
#include "core/json.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <optional>

#include "core/quoted_string.h"

namespace engine {

namespace {

const std::string kEmptyString;
const std::vector<Json> kNoItems;
const std::vector<std::pair<std::string, Json>> kNoMembers;
const Json kNull;

// Recursive descent over the text; positions become line:column in errors.
class Parser {
public:
    Parser(std::string_view text, std::string_view source) : mText(text), mSource(source) {}

    Result<Json> document() {
        Json value;
        if (!parseValue(value, 0)) return *mError;
        skipSpace();
        if (mPos != mText.size()) return error("unexpected text after the document");
        return value;
    }

private:
    static constexpr int kMaxDepth =
        256;  // deeper nesting is not a manifest: refuse, do not overflow

    Error error(std::string_view what) const {
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < mPos && i < mText.size(); ++i) {
            if (mText[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return makeError("{}:{}:{}: {}", mSource, line, column, what);
    }
    bool fail(std::string_view what) {
        if (!mError) mError = error(what);
        return false;
    }

    void skipSpace() {
        while (mPos < mText.size() && (mText[mPos] == ' ' || mText[mPos] == '\t' ||
                                       mText[mPos] == '\n' || mText[mPos] == '\r'))
            ++mPos;
    }
    bool literal(std::string_view word) {
        if (mText.substr(mPos, word.size()) != word) return false;
        mPos += word.size();
        return true;
    }

    bool parseValue(Json& out, int depth) {
        if (depth > kMaxDepth) return fail("nested too deeply");
        skipSpace();
        if (mPos >= mText.size()) return fail("unexpected end of the document");
        const char c = mText[mPos];
        if (c == '{') return parseObject(out, depth);
        if (c == '[') return parseArray(out, depth);
        if (c == '"') {
            std::string s;
            if (!parseString(s)) return false;
            out = Json(std::move(s));
            return true;
        }
        if (literal("true")) {
            out = Json(true);
            return true;
        }
        if (literal("false")) {
            out = Json(false);
            return true;
        }
        if (literal("null")) {
            out = Json();
            return true;
        }
        if (c == '-' || (c >= '0' && c <= '9')) return parseNumber(out);
        return fail(fmt::format("unexpected character '{}'", c));
    }

    bool parseObject(Json& out, int depth) {
        ++mPos;  // {
        out = Json::object();
        skipSpace();
        if (mPos < mText.size() && mText[mPos] == '}') {
            ++mPos;
            return true;
        }
        while (true) {
            skipSpace();
            if (mPos >= mText.size() || mText[mPos] != '"') return fail("expected a key in quotes");
            std::string key;
            if (!parseString(key)) return false;
            skipSpace();
            if (mPos >= mText.size() || mText[mPos] != ':')
                return fail("expected ':' after the key");
            ++mPos;
            Json value;
            if (!parseValue(value, depth + 1)) return false;
            out[key] = std::move(value);
            skipSpace();
            if (mPos < mText.size() && mText[mPos] == ',') {
                ++mPos;
                continue;
            }
            if (mPos < mText.size() && mText[mPos] == '}') {
                ++mPos;
                return true;
            }
            return fail("expected ',' or '}'");
        }
    }

    bool parseArray(Json& out, int depth) {
        ++mPos;  // [
        out = Json::array();
        skipSpace();
        if (mPos < mText.size() && mText[mPos] == ']') {
            ++mPos;
            return true;
        }
        while (true) {
            Json value;
            if (!parseValue(value, depth + 1)) return false;
            out.push(std::move(value));
            skipSpace();
            if (mPos < mText.size() && mText[mPos] == ',') {
                ++mPos;
                continue;
            }
            if (mPos < mText.size() && mText[mPos] == ']') {
                ++mPos;
                return true;
            }
            return fail("expected ',' or ']'");
        }
    }

    bool hex4(std::uint32_t& out) {
        if (mPos + 4 > mText.size()) return fail("expected four hex digits after \\u");
        out = 0;
        for (int i = 0; i < 4; ++i) {
            const char h = mText[mPos++];
            out <<= 4;
            if (h >= '0' && h <= '9')
                out |= std::uint32_t(h - '0');
            else if (h >= 'a' && h <= 'f')
                out |= std::uint32_t(h - 'a' + 10);
            else if (h >= 'A' && h <= 'F')
                out |= std::uint32_t(h - 'A' + 10);
            else
                return fail("expected four hex digits after \\u");
        }
        return true;
    }

    static void appendUtf8(std::string& s, std::uint32_t cp) {
        if (cp < 0x80) {
            s += char(cp);
        } else if (cp < 0x800) {
            s += char(0xC0 | (cp >> 6));
            s += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            s += char(0xE0 | (cp >> 12));
            s += char(0x80 | ((cp >> 6) & 0x3F));
            s += char(0x80 | (cp & 0x3F));
        } else {
            s += char(0xF0 | (cp >> 18));
            s += char(0x80 | ((cp >> 12) & 0x3F));
            s += char(0x80 | ((cp >> 6) & 0x3F));
            s += char(0x80 | (cp & 0x3F));
        }
    }

    bool parseString(std::string& out) {
        ++mPos;  // "
        while (mPos < mText.size()) {
            const char c = mText[mPos++];
            if (c == '"') return true;
            if (static_cast<unsigned char>(c) < 0x20) {
                --mPos;
                return fail("control character in a string (escape it)");
            }
            if (c != '\\') {
                out += c;
                continue;
            }
            if (mPos >= mText.size()) break;
            const char e = mText[mPos++];
            switch (e) {
                case '"':
                    out += '"';
                    break;
                case '\\':
                    out += '\\';
                    break;
                case '/':
                    out += '/';
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'u': {
                    std::uint32_t cp = 0;
                    if (!hex4(cp)) return false;
                    if (cp >= 0xD800 && cp < 0xDC00) {  // a surrogate pair
                        std::uint32_t low = 0;
                        if (!literal("\\u") || !hex4(low) || low < 0xDC00 || low >= 0xE000)
                            return fail("unpaired surrogate in \\u escape");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                    }
                    appendUtf8(out, cp);
                    break;
                }
                default:
                    --mPos;
                    return fail(fmt::format("unknown escape '\\{}'", e));
            }
        }
        return fail("unterminated string");
    }

    bool parseNumber(Json& out) {
        const std::size_t start = mPos;
        if (mText[mPos] == '-') ++mPos;
        auto digits = [&] {
            const std::size_t from = mPos;
            while (mPos < mText.size() && mText[mPos] >= '0' && mText[mPos] <= '9') ++mPos;
            return mPos > from;
        };
        if (!digits()) return fail("expected a digit");
        if (mPos < mText.size() && mText[mPos] == '.') {
            ++mPos;
            if (!digits()) return fail("expected a digit after '.'");
        }
        if (mPos < mText.size() && (mText[mPos] == 'e' || mText[mPos] == 'E')) {
            ++mPos;
            if (mPos < mText.size() && (mText[mPos] == '+' || mText[mPos] == '-')) ++mPos;
            if (!digits()) return fail("expected a digit in the exponent");
        }
        const std::string number(mText.substr(start, mPos - start));
        out = Json(std::strtod(number.c_str(), nullptr));
        return true;
    }

    std::string_view mText, mSource;
    std::size_t mPos = 0;
    std::optional<Error> mError;
};

}  // namespace

const std::string& Json::string() const { return mType == Type::String ? mString : kEmptyString; }

const std::vector<Json>& Json::items() const { return mType == Type::Array ? mItems : kNoItems; }

std::vector<Json>& Json::items() {
    if (mType == Type::Null) mType = Type::Array;
    return mItems;
}

void Json::push(Json value) {
    if (mType == Type::Null) mType = Type::Array;
    mItems.push_back(std::move(value));
}

const std::vector<std::pair<std::string, Json>>& Json::members() const {
    return mType == Type::Object ? mMembers : kNoMembers;
}

const Json* Json::find(std::string_view key) const {
    if (mType != Type::Object) return nullptr;
    for (const auto& [k, v] : mMembers)
        if (k == key) return &v;
    return nullptr;
}

const Json& Json::get(std::string_view key) const {
    const Json* v = find(key);
    return v ? *v : kNull;
}

Json& Json::operator[](std::string_view key) {
    if (mType == Type::Null) mType = Type::Object;
    for (auto& [k, v] : mMembers)
        if (k == key) return v;
    mMembers.emplace_back(std::string(key), Json());
    return mMembers.back().second;
}

bool Json::erase(std::string_view key) {
    auto it = std::find_if(mMembers.begin(), mMembers.end(),
                           [&](const auto& m) { return m.first == key; });
    if (it == mMembers.end()) return false;
    mMembers.erase(it);
    return true;
}

bool Json::operator==(const Json& other) const {
    if (mType != other.mType) return false;
    switch (mType) {
        case Type::Null:
            return true;
        case Type::Bool:
            return mBool == other.mBool;
        case Type::Number:
            return mNumber == other.mNumber;
        case Type::String:
            return mString == other.mString;
        case Type::Array:
            return mItems == other.mItems;
        case Type::Object:
            return mMembers == other.mMembers;
    }
    return false;
}

std::string Json::dump(int expandDepth) const {
    std::string out;
    dumpTo(out, 0, expandDepth);
    out += '\n';
    return out;
}

void Json::dumpTo(std::string& out, int depth, int expandDepth) const {
    switch (mType) {
        case Type::Null:
            out += "null";
            return;
        case Type::Bool:
            out += mBool ? "true" : "false";
            return;
        case Type::Number:
            // fmt's shortest round-trip form: reading it back gives the same double.
            out += std::isfinite(mNumber) ? fmt::format("{}", mNumber) : "null";
            return;
        case Type::String:
            out += quotedString(mString);
            return;
        case Type::Array:
        case Type::Object:
            break;
    }
    const bool isArr = mType == Type::Array;
    const std::size_t count = isArr ? mItems.size() : mMembers.size();
    const char open = isArr ? '[' : '{', close = isArr ? ']' : '}';
    if (count == 0) {
        out += open;
        out += close;
        return;
    }
    const bool expand = depth < expandDepth;
    std::string inner;
    if (expand) inner.append(1, '\n').append(2 * (depth + 1), ' ');
    out += open;
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0) out += expand ? "," : ", ";
        out += inner;
        if (isArr) {
            mItems[i].dumpTo(out, depth + 1, expandDepth);
        } else {
            out += quotedString(mMembers[i].first);
            out += ": ";
            mMembers[i].second.dumpTo(out, depth + 1, expandDepth);
        }
    }
    if (expand) out.append(1, '\n').append(2 * depth, ' ');
    out += close;
}

Result<Json> parseJson(std::string_view text, std::string_view source) {
    return Parser(text, source).document();
}

}  // namespace engine
