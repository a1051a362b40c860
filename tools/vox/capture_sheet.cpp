#include "capture_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/image_io.h"

namespace vox {

CaptureSheet::CaptureSheet(std::uint32_t first, std::uint32_t last, std::uint32_t thumbnails,
                           glm::uvec2 frameSize) {
    const std::uint32_t written = last - first + 1;
    const std::uint32_t thumbs = std::min(thumbnails, written);
    for (std::uint32_t s = 0; s < thumbs; ++s)
        mSlots[first + (thumbs > 1
                            ? std::uint32_t(std::llround(double(s) * (written - 1) / (thumbs - 1)))
                            : 0)] = s;
    const std::uint32_t thumbWidth = std::min<std::uint32_t>(frameSize.x, 160);
    const std::uint32_t thumbHeight =
        std::max<std::uint32_t>(1, frameSize.y * thumbWidth / frameSize.x);
    if (thumbs > 0) mSheet.emplace(thumbs, 6, thumbWidth, thumbHeight);
}

void CaptureSheet::place(std::uint32_t frame, std::span<const std::uint32_t> rgba8,
                         std::uint32_t width, std::uint32_t height) {
    if (auto it = mSlots.find(frame); it != mSlots.end() && mSheet)
        mSheet->place(it->second, rgba8, width, height);
}

engine::Status CaptureSheet::write(const std::filesystem::path& file) const {
    if (!mSheet) return {};
    if (engine::Status s =
            engine::io::writePng(file, mSheet->width(), mSheet->height(), mSheet->pixels());
        !s)
        return s;
    std::string frames;
    for (const auto& [frame, slot] : mSlots) {
        if (!frames.empty()) frames += ' ';
        frames += std::to_string(frame);
    }
    std::printf("wrote    %s (%zu thumbnails, frames %s)\n", file.string().c_str(), mSlots.size(),
                frames.c_str());
    return {};
}

}  // namespace vox
