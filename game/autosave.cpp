#include "game/autosave.h"

namespace game {

std::filesystem::path autosavePath(const std::filesystem::path& savePath) {
    std::filesystem::path p = savePath;
    p.replace_filename(savePath.stem().string() + ".autosave.toml");
    return p;
}

bool Autosave::due(double nowSeconds, std::uint64_t worldVersion) const {
    return mInterval > 0.0 && worldVersion != mWrittenVersion &&
           nowSeconds - mLastWrite >= mInterval;
}

void Autosave::written(double nowSeconds, std::uint64_t worldVersion) {
    mLastWrite = nowSeconds;
    mWrittenVersion = worldVersion;
}

}  // namespace game
