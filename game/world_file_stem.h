// A world's name as the stem of the files the sandbox names after it (saves/NAME.toml,
// screenshots/NAME-FRAME.png). A scene file's `name` is any text, so it is made safe: letters,
// digits, '-', '_', '.' and spaces kept, anything else '_', no leading dot or space (no "..", no
// hidden file), at most 64 bytes. A name that had to change gets 8 hex digits of a hash of the
// name as given ("untitled-1a2b3c4d" for ".", "" or "   "), so different names never share a file.
#pragma once

#include <string>
#include <string_view>

namespace game {

std::string worldFileStem(std::string_view worldName);

}  // namespace game
