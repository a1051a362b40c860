// `vox capture --join DIR`: a capture job's single result — one CSV in frame order (the rows the
// tasks recorded, so the columns one process would have written), one contact sheet from the
// frames' PNGs, one MP4 of all frames. It refuses, naming them, while any frame is missing,
// damaged (its file's size or checksum is not the recorded one) or made with other settings.
#pragma once

#include <filesystem>

namespace vox {

// Returns the exit status.
int joinCapture(const std::filesystem::path& dir);

}  // namespace vox
