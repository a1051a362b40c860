// The checked atomic writer: a failure at any write or at the fsync (injected as ENOSPC, a full
// disk) gives one line naming the path and the reason, removes the temporary and leaves the
// previous file byte-identical; a folder at the output path is refused up front; temporaries of
// dead processes are removed; an output folder (or a range of it) is claimed by one process.
#include "core/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "core/folder_lock.h"

namespace fs = std::filesystem;

namespace {

class Scratch {
public:
    Scratch() {
        char pattern[] = "/tmp/vox_atomic_XXXXXX";
        mPath = ::mkdtemp(pattern);
    }
    ~Scratch() {
        engine::failWritesAfter(std::nullopt);
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    fs::path operator/(const std::string& name) const { return mPath / name; }
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t filesIn(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

// A process id that is surely not running: a child that has exited and been reaped.
pid_t deadPid() {
    pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

}  // namespace

TEST(AtomicFile, ReplacesTheFileAndLeavesNoTemporary) {
    Scratch dir;
    const fs::path file = dir / "out.csv";
    ASSERT_TRUE(engine::writeFileAtomically(file, "old\n").ok());
    engine::Status s = engine::writeFileAtomically(file, [](engine::AtomicFile& f) {
        f.stream() << "a,b\n";
        for (int i = 0; i < 1000; ++i) f.stream() << i << "," << i * i << "\n";
        return f.status();
    });
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(bytesOf(file).substr(0, 8), "a,b\n0,0\n");
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

// Every operation in turn fails (writes of a stream larger than its 64 KiB buffer, then the
// fsync); each time the previous file survives and the message is one line with the reason.
TEST(AtomicFile, AFailureAtAnyWriteOrTheFsyncKeepsThePreviousFile) {
    Scratch dir;
    const fs::path file = dir / "data.bin";
    const std::string previous = "previous contents\n";
    ASSERT_TRUE(engine::writeFileAtomically(file, previous).ok());
    const std::string big(200 * 1024, 'x');
    std::uint64_t failures = 0;
    for (std::uint64_t n = 0; n < 20; ++n) {
        engine::failWritesAfter(n);
        engine::Status s = engine::writeFileAtomically(file, [&](engine::AtomicFile& f) {
            f.stream() << big;
            return f.status();
        });
        engine::failWritesAfter(std::nullopt);
        if (s.ok()) break;
        ++failures;
        const std::string& m = s.error().message;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        EXPECT_EQ(m.rfind(file.string() + ": cannot ", 0), 0u) << m;
        EXPECT_NE(m.find("No space left on device"), std::string::npos) << m;
        EXPECT_EQ(bytesOf(file), previous) << "after failing operation " << n;
        EXPECT_EQ(filesIn(dir.path()), 1u) << "a temporary was left after failing operation " << n;
    }
    EXPECT_GE(failures, 4u);  // 4 writes of 64 KiB and the fsync
    EXPECT_EQ(bytesOf(file), big);
}

TEST(AtomicFile, AReplacedFileKeepsItsPermissions) {
    Scratch dir;
    const fs::path file = dir / "private.toml";
    ASSERT_TRUE(engine::writeFileAtomically(file, "a").ok());
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
    ASSERT_TRUE(engine::writeFileAtomically(file, "b").ok());
    EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
}

// A writer that only takes a path (ffmpeg): its file is fsynced (checked) and renamed; a failed
// writer or fsync leaves the previous file and no temporary.
TEST(AtomicFile, APathWriterIsCheckedAndRenamedLikeAnyOther) {
    Scratch dir;
    const fs::path file = dir / "capture.mp4";
    ASSERT_TRUE(engine::writeFileAtomically(file, "previous").ok());
    auto writer = [](const fs::path& temp) -> engine::Status {
        std::ofstream(temp, std::ios::binary | std::ios::trunc) << "new video";
        return {};
    };
    engine::failWritesAfter(0);  // the fsync
    engine::Status s = engine::replaceFileAtomically(file, writer);
    engine::failWritesAfter(std::nullopt);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message, file.string() + ": cannot flush to disk: No space left on device");
    EXPECT_EQ(bytesOf(file), "previous");
    EXPECT_EQ(filesIn(dir.path()), 1u);
    s = engine::replaceFileAtomically(
        file, [](const fs::path&) -> engine::Status { return engine::makeError("ffmpeg failed"); });
    EXPECT_FALSE(s.ok());
    EXPECT_EQ(bytesOf(file), "previous");
    EXPECT_EQ(filesIn(dir.path()), 1u);
    ASSERT_TRUE(engine::replaceFileAtomically(file, writer).ok());
    EXPECT_EQ(bytesOf(file), "new video");
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(AtomicFile, AnOutputPathThatIsAFolderIsRefusedWithoutSuccess) {
    Scratch dir;
    const fs::path folder = dir / "out.png";
    fs::create_directory(folder);
    engine::Status s = engine::writeFileAtomically(folder, "x");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message.rfind(folder.string() + " is a folder", 0), 0u)
        << s.error().message;
    EXPECT_EQ(s.error().message.find("Success"), std::string::npos);
    EXPECT_TRUE(fs::is_directory(folder));
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(AtomicFile, TemporariesOfDeadProcessesAreRemoved) {
    Scratch dir;
    const pid_t dead = deadPid();
    const fs::path stale = dir / (".a.toml.tmp-" + std::to_string(dead));
    const fs::path staleOldStyle = dir / ("b.vdb.tmp-" + std::to_string(dead));
    const fs::path live = dir / ".c.png.tmp-1";  // init is alive
    const fs::path mine = dir / (".d.png.tmp-" + std::to_string(::getpid()));
    const fs::path notOurs = dir / "notes.tmp-draft";
    const fs::path usersFile =
        dir / ("notes.txt.tmp-" + std::to_string(dead));  // not an extension we write
    for (const fs::path& p : {stale, staleOldStyle, live, mine, notOurs, usersFile})
        std::ofstream(p) << "partial";
    EXPECT_EQ(engine::removeStaleTemporaries(dir.path()), 2u);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_FALSE(fs::exists(staleOldStyle));
    EXPECT_TRUE(fs::exists(live));
    EXPECT_TRUE(fs::exists(mine));
    EXPECT_TRUE(fs::exists(notOurs));
    EXPECT_TRUE(fs::exists(usersFile));
}

TEST(AtomicFile, TheFirstWriteIntoAFolderRemovesStaleTemporaries) {
    Scratch dir;
    const fs::path stale = dir / (".frame_00001.png.tmp-" + std::to_string(deadPid()));
    std::ofstream(stale) << "partial";
    ASSERT_TRUE(engine::writeFileAtomically(dir / "frame_00002.png", "png").ok());
    EXPECT_FALSE(fs::exists(stale));
}

// Record locks belong to processes: a child holds frames 0..9 of the folder while the parent
// asks for overlapping and disjoint ranges.
TEST(FolderLock, AnOverlappingClaimIsRefusedNamingTheHolder) {
    Scratch dir;
    int ready[2], done[2];
    ASSERT_EQ(::pipe(ready), 0);
    ASSERT_EQ(::pipe(done), 0);
    pid_t child = ::fork();
    if (child == 0) {
        auto held = engine::FolderLock::acquire(dir.path(), "vox capture", 0, 10);
        char c = held.ok() ? 'y' : 'n';
        (void)!::write(ready[1], &c, 1);
        (void)!::read(done[0], &c, 1);  // hold until the parent is finished
        ::_exit(0);
    }
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    ASSERT_EQ(c, 'y');
    auto overlapping = engine::FolderLock::acquire(dir.path(), "vox capture", 5, 10);
    auto whole = engine::FolderLock::acquire(dir.path(), "vox capture");
    auto disjoint = engine::FolderLock::acquire(dir.path(), "vox capture", 10, 5);
    (void)!::write(done[1], "x", 1);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_FALSE(overlapping.ok());
    EXPECT_EQ(overlapping.error().message, dir.path().string() +
                                               " is in use by another vox capture (pid " +
                                               std::to_string(child) + ")");
    EXPECT_FALSE(whole.ok());
    EXPECT_TRUE(disjoint.ok()) << disjoint.error().message;
    // The holder has exited: the kernel released its lock.
    EXPECT_TRUE(engine::FolderLock::acquire(dir.path(), "vox capture").ok());
}

// Issue 41, item 9: the temporary's name (.NAME.tmp-PID) is predictable, and it was opened
// without O_EXCL or O_NOFOLLOW, so a symlink planted there redirected the write and the chmod
// (to the previous file's mode) to the file it pointed at. Now the temporary is created
// exclusively and never followed: the planted link is removed, not written through.
TEST(AtomicFile, APlantedSymlinkAtTheTemporaryIsNotFollowed) {
    Scratch dir;
    const fs::path victim = dir / "victim.txt", file = dir / "out.toml";
    std::ofstream(victim) << "precious";
    const fs::perms victimMode = fs::perms::owner_read | fs::perms::owner_write |
                                 fs::perms::group_read | fs::perms::others_read;
    fs::permissions(victim, victimMode);
    ASSERT_TRUE(engine::writeFileAtomically(file, "old").ok());
    fs::permissions(file,
                    fs::perms::owner_read | fs::perms::owner_write);  // a followed chmod would show
    fs::create_symlink(victim, engine::temporaryPathFor(file));
    engine::Status s = engine::writeFileAtomically(file, "new");
    EXPECT_EQ(bytesOf(victim), "precious");
    EXPECT_EQ(fs::status(victim).permissions() & fs::perms::all, victimMode);
    EXPECT_FALSE(fs::is_symlink(file));
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(bytesOf(file), "new");
    EXPECT_EQ(filesIn(dir.path()), 2u);  // out.toml, victim.txt: the link is gone
}

// Issue 41, item 11: names of 245 to 255 bytes were refused ("File name too long"): the
// temporary's ".NAME.tmp-PID" is up to 13 bytes longer than NAME and went past NAME_MAX (255).
TEST(AtomicFile, FileNamesUpToTheLimitAreWrittenAndReplaced) {
    Scratch dir;
    const std::size_t lengths[] = {240, 245, 250, 254, 255};
    for (std::size_t length : lengths) {
        const fs::path file = dir / (std::string(length - 4, 'n') + ".png");
        engine::Status s = engine::writeFileAtomically(file, "first");
        ASSERT_TRUE(s.ok()) << length << ": " << s.error().message;
        s = engine::writeFileAtomically(file, "second");
        ASSERT_TRUE(s.ok()) << length << ": " << s.error().message;
        EXPECT_EQ(bytesOf(file), "second") << length;
        EXPECT_LE(engine::temporaryPathFor(file).filename().string().size(), 255u) << length;
    }
    EXPECT_EQ(filesIn(dir.path()), std::size(lengths));  // no temporary left
    // Long names that differ only at the end get different temporaries.
    EXPECT_NE(engine::temporaryPathFor(dir / (std::string(250, 'n') + "a.png")),
              engine::temporaryPathFor(dir / (std::string(250, 'n') + "b.png")));
}
