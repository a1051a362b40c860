// The one string escaper writes what TOML and JSON both read back.
#include "core/quoted_string.h"

#include <gtest/gtest.h>

TEST(QuotedString, EscapesQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(engine::quotedString("plain"), "\"plain\"");
    EXPECT_EQ(engine::quotedString("x\"y"), "\"x\\\"y\"");
    EXPECT_EQ(engine::quotedString("a\\b"), "\"a\\\\b\"");
    EXPECT_EQ(engine::quotedString("t\tn\nr\r"), "\"t\\tn\\nr\\r\"");
    EXPECT_EQ(engine::quotedString(std::string("\x01\x7f", 2)), "\"\\u0001\\u007F\"");
    EXPECT_EQ(engine::quotedString("é"), "\"é\"");  // UTF-8 passes through
}

TEST(PrintableText, ControlCharactersAndBytesThatAreNotUtf8BecomeEscapes) {
    using engine::printableText;
    EXPECT_EQ(printableText("plain 'name' \"x\" a\\b é ✓ 😀"), "plain 'name' \"x\" a\\b é ✓ 😀");
    EXPECT_EQ(printableText("two\nlines\r\ttab"),
              "two\\nlines\\r\ttab");  // a tab stays: a wide space
    EXPECT_EQ(printableText("\x1b]2;title\x07\x1b[31mred"), "\\u001B]2;title\\u0007\\u001B[31mred");
    EXPECT_EQ(printableText(std::string("nul\0cut", 7)), "nul\\u0000cut");
    EXPECT_EQ(printableText("del\x7f"), "del\\u007F");
    EXPECT_EQ(printableText("\xc2\x9b"
                            "31m"),
              "\\u009B31m");  // C1 CSI, encoded
    EXPECT_EQ(printableText("\x9b"
                            "31m"),
              "\\x9B31m");                                        // a bare byte, not UTF-8
    EXPECT_EQ(printableText("\xc3"), "\\xC3");                    // cut short
    EXPECT_EQ(printableText("\xc0\xaf"), "\\xC0\\xAF");           // overlong
    EXPECT_EQ(printableText("\xed\xa0\x80"), "\\xED\\xA0\\x80");  // a surrogate
    // No control character is left in it but tabs.
    std::string all;
    for (int b = 0; b < 256; ++b) all += char(b);
    for (char c : printableText(all)) {
        EXPECT_FALSE((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
            << int(static_cast<unsigned char>(c));
    }
}
