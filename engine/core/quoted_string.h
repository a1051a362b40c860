// The one string escaper: a double-quoted string whose escapes (\" \\ \n \t \r \uXXXX) read
// back the same in a TOML basic string and in JSON, so scene files and JSON records share it.
#pragma once

#include <string>
#include <string_view>

namespace engine {

std::string quotedString(std::string_view text);

}  // namespace engine
