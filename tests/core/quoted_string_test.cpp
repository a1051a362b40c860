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
