// A claim on an output folder, or on a range of it, for the life of this object: a POSIX record
// lock (fcntl, non-blocking) on bytes [begin, begin + count) of FOLDER/.lock. A range lets runs
// that write disjoint parts share a folder (the slices of one capture, frames A..B each) while two
// runs that would write the same files cannot. A refusal names the holder's process id, which the
// kernel reports (F_GETLK). The kernel drops the lock when the process ends, however it ends, so a
// killed run never leaves the folder locked; the .lock file itself stays (removing it would race
// with a new owner).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

#include "core/error.h"

namespace engine {

class FolderLock {
public:
    FolderLock() = default;
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;
    FolderLock(FolderLock&& other) noexcept : mFd(other.mFd) { other.mFd = -1; }

    // Without waiting. Refuses with "WHAT is in use by another OWNER (pid N)" if another process
    // holds an overlapping range; `owner` names the kind of program ("vox capture"), `what` the
    // thing claimed (default: the folder). count 0: the whole folder. Record locks belong to the
    // process: a second claim by the same process is not refused.
    static Result<FolderLock> acquire(const std::filesystem::path& folder, std::string_view owner,
                                      std::uint64_t begin = 0, std::uint64_t count = 0,
                                      std::string_view what = {});

private:
    explicit FolderLock(int fd) : mFd(fd) {}
    int mFd = -1;
};

}  // namespace engine
