// Symbol-table pages: give back the pages the dynamic linker read at start-up and will not read
// again.
//
// Why: Debian links libopenvdb BIND_NOW, so before main() the dynamic linker resolves all of its
// 69 000 symbol references, reading its symbol names (22 MB of mangled template names) and hash
// tables. Those pages then stay in every vox process's resident set: 26 MB, more than half of
// what `vox import` of a 10^7-voxel world holds beyond the world itself. They are clean pages of
// a read-only file mapping, so dropping them is safe: if anything reads them again (a later
// dlopen resolving against the library) the kernel maps them back in from the file.
//
// Per loaded library, only the load segment holding its dynamic string table is released, and
// only if it is read-only, not executable, never written (not RELRO, no text relocations): with
// the default linker layout that segment holds the symbol, string and hash tables and the
// relocation entries, and nothing the program reads while it runs.
#pragma once

#include <cstddef>

namespace engine {

struct ReleasedPages {
    std::size_t bytes = 0;     // resident or not: the size of the ranges advised away
    std::size_t segments = 0;  // how many load segments they came from
};

// Linux only (madvise MADV_DONTNEED); elsewhere it releases nothing. Segments smaller than
// minSegmentBytes are left alone: not worth a system call.
ReleasedPages releaseSymbolTablePages(std::size_t minSegmentBytes = 1u << 20);

}  // namespace engine
