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
    // True when that request was refused by the per-allocation ceiling (below the budget), which
    // a larger budget would not lift.
    bool refusedAsSingleRequest() const;
    std::uint64_t singleBytes() const { return mSingle; }  // the per-allocation ceiling
    std::uint64_t peakBytes() const;
    std::uint64_t totalBytes() const { return mTotal; }

    // Throws std::bad_alloc, counted as a refused request, when `bytes` more would not fit in the
    // active budget; for callers that know the size of a coming burst of small allocations and
    // must not be interrupted half way (a library that is not exception-safe). No-op without a
    // budget.
    static void require(std::uint64_t bytes);

    // For calls into code that is not exception-safe when an allocation fails (OpenVDB's tree
    // reading leaks or corrupts state): require(bytes) on entry, then let the total be exceeded
    // without throwing inside the call; finish() throws, at a safe point, if it was. The
    // per-allocation ceiling still applies.
    class Headroom {
    public:
        explicit Headroom(std::uint64_t bytes);
        ~Headroom();
        Headroom(const Headroom&) = delete;
        Headroom& operator=(const Headroom&) = delete;
        void finish();

    private:
        bool mWasSoft;
    };

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
    std::uint64_t mSingle;
};

}  // namespace engine
