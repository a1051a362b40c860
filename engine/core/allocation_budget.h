// Allocation budget: while one is active, every heap allocation made through operator new (by
// the engine or by a library it calls, such as OpenVDB) is counted, and a request that would take
// the net total over the budget, or a single request over the per-allocation ceiling, throws
// std::bad_alloc instead of reaching malloc.
//
// Why: a hostile or damaged input can make a parser ask for absurd amounts of memory from a few
// bytes — OpenVDB reads a 32-bit string length and fills a string of that size before noticing
// the file has ended, and a few kilobytes of compressed tree nodes can expand to gigabytes. The
// budget turns that into an ordinary, reportable failure at the io boundary. Allocations that
// bypass operator new (mmap, TBB's scalable allocator) are not counted.
//
// Costs one relaxed atomic load per allocation when no budget is active. One budget at a time.
#pragma once

#include <cstdint>

namespace engine {

class AllocationBudget {
public:
    AllocationBudget(std::uint64_t totalBytes, std::uint64_t singleBytes);
    ~AllocationBudget();
    AllocationBudget(const AllocationBudget&) = delete;
    AllocationBudget& operator=(const AllocationBudget&) = delete;

    // True once a request was refused; the bad_alloc that followed came from the budget.
    bool exceeded() const;
    std::uint64_t refusedBytes() const;  // size of the first refused request
    std::uint64_t usedBytes() const;     // net bytes allocated since the budget began
    std::uint64_t peakBytes() const;
    std::uint64_t totalBytes() const { return mTotal; }

    // Within its scope, single requests up to the whole budget are allowed: for the engine's own
    // large buffers (the world's top grid and brick pool), which are sized from checked figures.
    class LargeAllocations {
    public:
        LargeAllocations();
        ~LargeAllocations();
        LargeAllocations(const LargeAllocations&) = delete;
        LargeAllocations& operator=(const LargeAllocations&) = delete;

    private:
        std::uint64_t mSaved;
    };

private:
    std::uint64_t mTotal;
};

}  // namespace engine
