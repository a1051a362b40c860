// The process's memory budget: how much a world (its CPU grid, its GPU mirror, the frame's
// buffers) may take before the engine refuses it with one line instead of failing inside an
// allocation. Default: three quarters of physical memory, or of the address-space limit
// (ulimit -v) when that is lower. On a software Vulkan device "GPU" memory is host memory too.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace engine {

std::uint64_t physicalMemoryBytes();
std::uint64_t defaultMemoryBudgetBytes();
std::uint64_t memoryBudgetBytes();  // the default until set
void setMemoryBudgetBytes(std::uint64_t bytes);

// True when the address-space limit (ulimit -v) is what caps a budget this large: the budget is
// three quarters of the limit or more, so raising --memory-budget cannot help.
bool addressSpaceLimits(std::uint64_t budgetBytes);
// What to change for more than `budgetBytes`, for a message refusing for want of memory: "raise
// ulimit -v (now 390 MiB; ...)" when that limit binds, else "raise --memory-budget if the machine
// has the memory".
std::string memoryBudgetAdvice(std::uint64_t budgetBytes);

// Thrown where a plan shows the budget would be exceeded deep inside a frame (a new world reaching
// the renderer); caught with std::bad_alloc at the top of a program, which prints what() as one
// line.
class MemoryBudgetExceeded : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace engine
