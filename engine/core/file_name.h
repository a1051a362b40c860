// File names the engine makes from the user's (a temporary `.NAME.tmp-PID`, a payload
// `STEM.N.vdb`, a manifest): one folder entry holds at most 255 bytes (NAME_MAX on Linux file
// systems), so a name that would be longer is shortened, the same way every time and never to
// another long name's result.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace engine {

inline constexpr std::size_t kMaxFileName = 255;  // NAME_MAX

// `name` if it has at most `room` bytes; else its first bytes (whole UTF-8 characters), '~' and 16
// hex digits of a hash of all of it, `room` bytes at most.
std::string fitFileName(std::string_view name, std::size_t room);

}  // namespace engine
