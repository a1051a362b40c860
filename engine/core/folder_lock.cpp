#include "core/folder_lock.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace engine {

FolderLock::~FolderLock() {
    if (mFd >= 0) ::close(mFd);  // releases the lock
}

Result<FolderLock> FolderLock::acquire(const std::filesystem::path& folder, std::string_view owner,
                                       std::uint64_t begin, std::uint64_t count,
                                       std::string_view what) {
    const std::filesystem::path file = folder / ".lock";
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0)
        return makeError("{}: cannot create the lock file: {}", file.string(),
                         std::strerror(errno));
    struct flock range {};
    range.l_type = F_WRLCK;
    range.l_whence = SEEK_SET;
    range.l_start = off_t(begin);
    range.l_len = off_t(count);  // 0: to the end, however far
    if (::fcntl(fd, F_SETLK, &range) == 0) return FolderLock(fd);
    const int error = errno;
    if (error != EACCES && error != EAGAIN) {
        ::close(fd);
        return makeError("{}: cannot lock: {}", file.string(), std::strerror(error));
    }
    struct flock holder = range;
    const bool known =
        ::fcntl(fd, F_GETLK, &holder) == 0 && holder.l_type != F_UNLCK && holder.l_pid > 0;
    ::close(fd);
    const std::string claimed = what.empty() ? folder.string() : std::string(what);
    if (known)
        return makeError("{} is in use by another {} (pid {})", claimed, owner, long(holder.l_pid));
    return makeError("{} is in use by another {}", claimed, owner);
}

}  // namespace engine
