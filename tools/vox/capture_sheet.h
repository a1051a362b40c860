// A capture's contact sheet (docs/CAPTURE.md#outputs): `sheet` thumbnails of frames spread evenly
// from the first to the last written frame, both included, 6 per row, at most 160 px wide. A
// whole capture fills it as it renders; a job's join fills it from the frames' PNGs — the same
// pixels, so the same sheet.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "core/error.h"
#include "io/contact_sheet.h"

namespace vox {

class CaptureSheet {
public:
    CaptureSheet(std::uint32_t first, std::uint32_t last, std::uint32_t thumbnails,
                 glm::uvec2 frameSize);

    bool wants(std::uint32_t frame) const { return mSlots.count(frame) > 0; }
    // Places `frame` when it is one of the thumbnails.
    void place(std::uint32_t frame, std::span<const std::uint32_t> rgba8, std::uint32_t width,
               std::uint32_t height);
    // Writes the sheet (when it has thumbnails) and prints "wrote    FILE (N thumbnails, frames
    // …)".
    engine::Status write(const std::filesystem::path& file) const;
    const std::map<std::uint32_t, std::uint32_t>& slots() const { return mSlots; }  // frame -> slot

private:
    std::map<std::uint32_t, std::uint32_t> mSlots;
    std::optional<engine::io::ContactSheet> mSheet;
};

}  // namespace vox
