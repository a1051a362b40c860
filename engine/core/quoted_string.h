// The string escapers: one for text written into files, one for text shown in messages.
//
// quotedString: a double-quoted string whose escapes (\" \\ \n \t \r \uXXXX) read back the same
// in a TOML basic string and in JSON, so scene files and JSON records share it.
//
// printableText: text from a file (a name, a key, a value) as a message shows it. Control
// characters -- C0 but the tab, DEL and C1 -- become the same escapes (\n, \r, \u001B,
// \u009B) and bytes that are not UTF-8 become \xNN, so the text cannot act on the terminal
// (escape sequences), split a one-line message (newlines) or cut it short (NUL). Quotes and
// backslashes stay as they are: the message puts the text in quotes of its own.
#pragma once

#include <string>
#include <string_view>

namespace engine {

std::string quotedString(std::string_view text);
std::string printableText(std::string_view text);

}  // namespace engine
