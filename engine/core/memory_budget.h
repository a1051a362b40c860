// The process's memory budget: how much a world (its CPU grid, its GPU mirror, the frame's
// buffers) may take before the engine refuses it with one line instead of failing inside an
// allocation. Default: three quarters of physical memory, or of the address-space limit
// (ulimit -v) when that is lower. On a software Vulkan device "GPU" memory is host memory too.
#pragma once

#include <cstdint>
#include <stdexcept>

namespace engine {

std::uint64_t physicalMemoryBytes();
std::uint64_t defaultMemoryBudgetBytes();
std::uint64_t memoryBudgetBytes();  // the default until set
void setMemoryBudgetBytes(std::uint64_t bytes);

// Thrown where a plan shows the budget would be exceeded deep inside a frame (a new world reaching
// the renderer); caught with std::bad_alloc at the top of a program, which prints what() as one line.
class MemoryBudgetExceeded : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace engine
