#include "core/symbol_table_pages.h"

#if defined(__linux__)
#include <cstdint>
#include <elf.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace engine {

#if defined(__linux__)
namespace {

struct ReleaseState {
    ReleasedPages released;
    std::size_t minSegmentBytes = 0;
};

struct Range {
    std::uintptr_t begin = 0, end = 0;
    bool overlaps(Range o) const { return begin < o.end && o.begin < end; }
};

// The dynamic section: whether the object has text relocations (then its read-only pages may be
// modified copies, never released) and where its dynamic string table lies.
struct DynamicInfo {
    bool textRelocations = false;
    std::uintptr_t stringTable = 0;
};

DynamicInfo readDynamic(const dl_phdr_info& info) {
    DynamicInfo result;
    for (int i = 0; i < info.dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info.dlpi_phdr[i];
        if (ph.p_type != PT_DYNAMIC) continue;
        const auto* dyn = reinterpret_cast<const ElfW(Dyn)*>(info.dlpi_addr + ph.p_vaddr);
        for (; dyn->d_tag != DT_NULL; ++dyn) {
            if (dyn->d_tag == DT_TEXTREL) result.textRelocations = true;
            if (dyn->d_tag == DT_FLAGS && (dyn->d_un.d_val & DF_TEXTREL))
                result.textRelocations = true;
            // glibc relocates these entries in place on some targets and not on others.
            if (dyn->d_tag == DT_STRTAB)
                result.stringTable = dyn->d_un.d_ptr >= info.dlpi_addr
                                         ? dyn->d_un.d_ptr
                                         : info.dlpi_addr + dyn->d_un.d_ptr;
        }
    }
    return result;
}

int releaseObject(dl_phdr_info* info, std::size_t, void* data) {
    auto& state = *static_cast<ReleaseState*>(data);
    if (info->dlpi_name == nullptr || info->dlpi_name[0] == '\0')
        return 0;  // the executable, the vdso
    const DynamicInfo dynamic = readDynamic(*info);
    if (dynamic.textRelocations || dynamic.stringTable == 0) return 0;

    Range relro;
    for (int i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        if (ph.p_type == PT_GNU_RELRO)
            relro = {info->dlpi_addr + ph.p_vaddr, info->dlpi_addr + ph.p_vaddr + ph.p_memsz};
    }
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    for (int i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        if (ph.p_type != PT_LOAD || ph.p_flags != PF_R || ph.p_filesz != ph.p_memsz) continue;
        // Whole pages only, so no neighbouring segment's page is touched.
        std::uintptr_t start = info->dlpi_addr + ph.p_vaddr;
        if (dynamic.stringTable < start || dynamic.stringTable >= start + ph.p_memsz) continue;
        Range pages{(start + page - 1) & ~(page - 1), (start + ph.p_memsz) & ~(page - 1)};
        if (pages.end <= pages.begin || pages.end - pages.begin < state.minSegmentBytes) continue;
        if (pages.overlaps(relro)) continue;
        if (madvise(reinterpret_cast<void*>(pages.begin), pages.end - pages.begin, MADV_DONTNEED) !=
            0)
            continue;
        state.released.bytes += pages.end - pages.begin;
        ++state.released.segments;
    }
    return 0;
}

}  // namespace

ReleasedPages releaseSymbolTablePages(std::size_t minSegmentBytes) {
    ReleaseState state{{}, minSegmentBytes};
    dl_iterate_phdr(releaseObject, &state);
    return state.released;
}

#else

ReleasedPages releaseSymbolTablePages(std::size_t) { return {}; }

#endif

}  // namespace engine
