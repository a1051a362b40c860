// The escapers of core/quoted_string.h.
#include "core/quoted_string.h"

#include <fmt/format.h>

namespace engine {

namespace {

// \n, \t, \r, or \uXXXX: the escapes TOML, JSON and a reader of a message all read.
void appendControl(std::string& out, unsigned code) {
    switch (code) {
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\r':
            out += "\\r";
            break;
        default:
            out += fmt::format("\\u{:04X}", code);
    }
}

bool isControl(unsigned code) { return code < 0x20 || code == 0x7f; }

// The length of the UTF-8 sequence starting at text[i] and its code point, or 0 when the bytes
// there are not one (a stray continuation byte, an overlong form, a surrogate, past U+10FFFF).
std::size_t utf8Sequence(std::string_view text, std::size_t i, unsigned& code) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned lead = byte(i);
    std::size_t n;
    unsigned min;
    if (lead >= 0xC2 && lead <= 0xDF)
        n = 2, code = lead & 0x1F, min = 0x80;
    else if (lead >= 0xE0 && lead <= 0xEF)
        n = 3, code = lead & 0x0F, min = 0x800;
    else if (lead >= 0xF0 && lead <= 0xF4)
        n = 4, code = lead & 0x07, min = 0x10000;
    else
        return 0;
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
    return n;
}

}  // namespace

std::string quotedString(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        const auto code = static_cast<unsigned char>(c);
        if (c == '"')
            out += "\\\"";
        else if (c == '\\')
            out += "\\\\";
        // TOML forbids raw control characters and DEL; JSON accepts the escape too.
        else if (isControl(code))
            appendControl(out, code);
        else
            out += c;
    }
    return out + "\"";
}

std::string printableText(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x80) {
            if (isControl(byte) && byte != '\t')
                appendControl(out, byte);  // a tab is only a wide space
            else
                out += text[i];
            ++i;
            continue;
        }
        unsigned code = 0;
        const std::size_t n = utf8Sequence(text, i, code);
        if (n == 0) {
            out += fmt::format("\\x{:02X}", byte);
            ++i;
        } else {
            if (code <= 0x9F)
                appendControl(out, code);  // C1: 0x9B alone starts an escape sequence
            else
                out.append(text.substr(i, n));
            i += n;
        }
    }
    return out;
}

}  // namespace engine
