// The one way the engine writes a file: into a temporary beside the target (`.NAME.tmp-PID`,
// NAME shortened if that would pass the 255-byte limit of a file name; created exclusively,
// never through a symlink planted at its name), every write, the fsync and the close checked,
// then renamed over the target. On any failure
// the temporary is removed and the previous file stays byte-identical; the error is one line
// naming the path and the system's reason ("r.png: cannot write: No space left on device").
// An output path that is an existing folder is refused before anything is written.
//
// Temporaries left by processes that died mid-write (kill -9, power loss) are recognised by
// their name and removed when this process first writes into the same folder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string_view>

#include "core/error.h"

namespace engine {

class AtomicFile {
public:
    AtomicFile();
    ~AtomicFile();  // abandons the temporary unless commit() succeeded
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Creates the temporary for `target`; refuses a target that is a folder or whose folder
    // does not exist.
    Status open(const std::filesystem::path& target);

    // Checked writes; the first failure sticks (later writes do nothing) and commit() reports it.
    Status write(const void* data, std::size_t bytes);
    Status write(std::string_view text) { return write(text.data(), text.size()); }
    // A stream over write() for writers that take a std::ostream (TOML, CSV, OpenVDB); a failed
    // write sets its badbit and the error is kept for commit().
    std::ostream& stream();
    // The first write error so far, if any.
    Status status() const { return mError ? Status(*mError) : Status(); }
    // Position and seek, for formats that patch a table after the data (OpenEXR).
    std::uint64_t tell() const;
    Status seek(std::uint64_t position);

    // fsync, close, rename over the target. The first error of any step (or of an earlier write)
    // is returned and the temporary removed.
    Status commit();
    // Removes the temporary; the target is untouched.
    void abandon();

    const std::filesystem::path& target() const { return mTarget; }
    const std::filesystem::path& temporary() const { return mTemporary; }

private:
    class Buffer;
    friend Status replaceFileAtomically(const std::filesystem::path&,
                                        const std::function<Status(const std::filesystem::path&)>&);
    Status writeDirect(const void* data, std::size_t bytes);
    void recordError(std::string_view what, int error);  // keeps the first
    Status fail(std::string_view what, int error);       // records, returns the first

    std::filesystem::path mTarget, mTemporary;
    int mFd = -1;
    std::uint64_t mPosition = 0;  // of the file descriptor (buffered bytes not included)
    std::optional<Error> mError;
    std::unique_ptr<Buffer> mBuffer;
    std::unique_ptr<std::ostream> mStream;
};

// The whole file at once.
Status writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);
// `write` fills the file (through file.write or file.stream()); committed if it and every write
// succeeded.
Status writeFileAtomically(const std::filesystem::path& target,
                           const std::function<Status(AtomicFile& file)>& write);
// For a writer that only takes a path (an external program like ffmpeg): it writes the
// temporary path it is given; the result is then fsynced (checked) and renamed like any other.
Status replaceFileAtomically(
    const std::filesystem::path& target,
    const std::function<Status(const std::filesystem::path& temporary)>& writeTo);

// `.NAME.tmp-PID` for `target`, in the target's folder (core/file_name.h shortens a long NAME).
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);
// Removes temporaries (`.NAME.tmp-PID`, and the older `NAME.tmp-PID` for the extensions the
// engine writes) whose process is no longer alive from `folder`; returns how many.
// AtomicFile::open calls it once per folder and process, scene/world_pair.h on every save.
std::size_t removeStaleTemporaries(const std::filesystem::path& folder);

// Failure injection for tests: after `operations` more successful writes/fsyncs (counted over
// every AtomicFile of the process), each later one fails with ENOSPC, as on a full disk.
// std::nullopt turns it off. The environment variable VOX_FAIL_WRITES=after:N does the same
// for a whole process (read once, at the first write), so the command-line tests can use it.
void failWritesAfter(std::optional<std::uint64_t> operations);

}  // namespace engine
