#include "core/memory_budget.h"

#include <algorithm>
#include <atomic>
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

namespace engine {

namespace {

std::atomic<std::uint64_t> gBudget{0};  // 0: not set

// The address-space limit (ulimit -v) in bytes, or 0 when there is none.
std::uint64_t addressSpaceLimit() {
    rlimit as{};
    if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) return as.rlim_cur;
    return 0;
}

}  // namespace

std::uint64_t physicalMemoryBytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return 4ull << 30;  // unknown: assume a small machine
    return std::uint64_t(pages) * std::uint64_t(pageSize);
}

std::uint64_t defaultMemoryBudgetBytes() {
    std::uint64_t limit = physicalMemoryBytes();
    // The address-space limit also pays for code, thread stacks and the Vulkan driver's own
    // reservations; three quarters leaves room for them.
    if (const std::uint64_t as = addressSpaceLimit()) limit = std::min<std::uint64_t>(limit, as);
    return limit / 4 * 3;
}

bool addressSpaceLimits(std::uint64_t budgetBytes) {
    const std::uint64_t as = addressSpaceLimit();
    return as && budgetBytes >= as / 4 * 3;
}

std::string memoryBudgetAdvice(std::uint64_t budgetBytes) {
    if (addressSpaceLimits(budgetBytes))
        return fmt::format(
            "raise ulimit -v (now {} MiB; the budget is at most three quarters of it)",
            addressSpaceLimit() >> 20);
    return "raise --memory-budget if the machine has the memory";
}

std::uint64_t memoryBudgetBytes() {
    const std::uint64_t set = gBudget.load(std::memory_order_relaxed);
    return set ? set : defaultMemoryBudgetBytes();
}

void setMemoryBudgetBytes(std::uint64_t bytes) { gBudget.store(bytes, std::memory_order_relaxed); }

}  // namespace engine
