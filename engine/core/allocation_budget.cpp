#include "core/allocation_budget.h"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <malloc.h>
#include <new>

#include "core/check.h"

namespace engine {

namespace {

std::atomic<bool> gActive{false};
std::atomic<std::int64_t> gUsed{0};
std::atomic<std::int64_t> gPeak{0};
std::atomic<std::uint64_t> gTotalLimit{0};
std::atomic<std::uint64_t> gSingleLimit{0};
std::atomic<std::uint64_t> gRefused{0};
std::atomic<bool> gRefusedAsSingle{false};  // the first refusal was the per-allocation ceiling's
std::atomic<bool> gSoft{false};             // inside a Headroom: the total may be exceeded

void* allocate(std::size_t n, std::size_t align) {
    const bool active = gActive.load(std::memory_order_relaxed);
    if (active) [[unlikely]] {
        std::int64_t used = gUsed.load(std::memory_order_relaxed);
        std::uint64_t after = used > 0 ? std::uint64_t(used) + n : n;
        const bool single = n > gSingleLimit.load(std::memory_order_relaxed);
        if (single || (after > gTotalLimit.load(std::memory_order_relaxed) &&
                       !gSoft.load(std::memory_order_relaxed))) {
            std::uint64_t none = 0;
            // "Single" when the ceiling, not the budget, was the limit: a larger budget would not
            // lift it (the ceiling equals the budget only when the budget is the smaller).
            if (gRefused.compare_exchange_strong(none, n ? n : 1))
                gRefusedAsSingle = single && gSingleLimit.load(std::memory_order_relaxed) <
                                                 gTotalLimit.load(std::memory_order_relaxed);
            throw std::bad_alloc();
        }
    }
    void* p = nullptr;
    if (align > alignof(std::max_align_t)) {
        if (::posix_memalign(&p, align, n ? n : 1) != 0) p = nullptr;
    } else {
        p = std::malloc(n ? n : 1);
    }
    if (!p) throw std::bad_alloc();
    if (active) [[unlikely]] {
        std::int64_t now =
            gUsed.fetch_add(std::int64_t(::malloc_usable_size(p)), std::memory_order_relaxed) +
            std::int64_t(::malloc_usable_size(p));
        std::int64_t peak = gPeak.load(std::memory_order_relaxed);
        while (now > peak && !gPeak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
        }
    }
    return p;
}

void release(void* p) noexcept {
    if (!p) return;
    if (gActive.load(std::memory_order_relaxed)) [[unlikely]]
        gUsed.fetch_sub(std::int64_t(::malloc_usable_size(p)), std::memory_order_relaxed);
    std::free(p);
}

}  // namespace

AllocationBudget::AllocationBudget(std::uint64_t totalBytes, std::uint64_t singleBytes)
    : mTotal(totalBytes) {
    CHECK_MSG(!gActive.load(), "only one AllocationBudget may be active");
    gUsed = 0;
    gPeak = 0;
    gRefused = 0;
    gRefusedAsSingle = false;
    gTotalLimit = totalBytes;
    gSingleLimit = singleBytes < totalBytes ? singleBytes : totalBytes;
    mSingle = gSingleLimit;
    gActive = true;
}

AllocationBudget::~AllocationBudget() {
    gActive = false;
    gSoft = false;
}

bool AllocationBudget::exceeded() const { return gRefused.load() != 0; }
std::uint64_t AllocationBudget::refusedBytes() const { return gRefused.load(); }
bool AllocationBudget::refusedAsSingleRequest() const {
    return gRefused.load() != 0 && gRefusedAsSingle.load();
}
std::uint64_t AllocationBudget::peakBytes() const {
    std::int64_t p = gPeak.load();
    return p > 0 ? std::uint64_t(p) : 0;
}

void AllocationBudget::require(std::uint64_t bytes) {
    if (!gActive.load()) return;
    std::int64_t used = gUsed.load();
    std::uint64_t after = (used > 0 ? std::uint64_t(used) : 0) + bytes;
    if (after > gTotalLimit.load()) {
        std::uint64_t none = 0;
        gRefused.compare_exchange_strong(none, bytes ? bytes : 1);
        throw std::bad_alloc();
    }
}

AllocationBudget::Headroom::Headroom(std::uint64_t bytes) : mWasSoft(gSoft.load()) {
    require(bytes);
    gSoft = true;
}
AllocationBudget::Headroom::~Headroom() { gSoft = mWasSoft; }
void AllocationBudget::Headroom::finish() {
    gSoft = mWasSoft;
    require(0);
}

AllocationBudget::LargeAllocations::LargeAllocations() : mSaved(gSingleLimit.load()) {
    gSingleLimit = gTotalLimit.load();
}
AllocationBudget::LargeAllocations::~LargeAllocations() { gSingleLimit = mSaved; }

}  // namespace engine

// Replacements of the global allocation functions ([new.delete]); all route through
// allocate()/release() above so a budget sees every operator new in the process.
void* operator new(std::size_t n) { return engine::allocate(n, 0); }
void* operator new[](std::size_t n) { return engine::allocate(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) {
    return engine::allocate(n, std::size_t(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return engine::allocate(n, std::size_t(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return engine::allocate(n, 0);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return engine::allocate(n, 0);
    } catch (...) {
        return nullptr;
    }
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    try {
        return engine::allocate(n, std::size_t(a));
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    try {
        return engine::allocate(n, std::size_t(a));
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept { engine::release(p); }
void operator delete[](void* p) noexcept { engine::release(p); }
void operator delete(void* p, std::size_t) noexcept { engine::release(p); }
void operator delete[](void* p, std::size_t) noexcept { engine::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { engine::release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { engine::release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { engine::release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { engine::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { engine::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { engine::release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    engine::release(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    engine::release(p);
}
