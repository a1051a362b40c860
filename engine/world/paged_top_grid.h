// PagedTopGrid: the top grid of a BrickGrid (one uint per 8^3 cell), paged by region
// (world/region.h). A region table holds one page number per region of 16^3 cells; a page holds
// its region's 4096 cells (x fastest) and a byte of marks per cell (the grid's dirty and touched
// flags). Page 0 is one shared page of empty cells, never written: every region without a
// non-empty cell maps to it, so the top grid's memory follows what the world holds, not its size
// (a 16384 x 512 x 16384 world's table is 64 Ki entries where a dense top grid would be 1 GiB).
//
// A write of a non-empty value into a region on page 0 gives the region a page of its own. A
// page whose cells all become empty again is released only by releaseEmptyPages() (BrickGrid
// calls it from clearDirty()), so marks and the cell lists that name a page's cells stay valid
// until every consumer of a frame's changes has seen them. Regions whose table entry changed
// since the last clearRegionChanges() are listed for the GPU mirror (render/gpu_world.h), which
// holds the same table and pages: a page number reused by another region is uploaded whole.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <vector>

#include "shared/brick_grid.h"
#include "world/region.h"

namespace engine::world {

class PagedTopGrid {
public:
    static constexpr int kPageCells = kRegionCells * kRegionCells * kRegionCells;
    static constexpr std::uint32_t kEmptyPage = 0;
    static_assert(kRegionCellsShift == int(shared::REGION_CELLS_SHIFT) &&
                  kPageCells == int(shared::PAGE_CELLS));

    explicit PagedTopGrid(glm::ivec3 sizeInCells);
    PagedTopGrid(const PagedTopGrid& other);
    PagedTopGrid& operator=(const PagedTopGrid& other);
    PagedTopGrid(PagedTopGrid&&) noexcept = default;
    PagedTopGrid& operator=(PagedTopGrid&&) noexcept = default;

    glm::ivec3 sizeInRegions() const { return mSizeInRegions; }
    std::size_t regionIndex(glm::ivec3 cell) const {
        const glm::ivec3 r = cell >> kRegionCellsShift;
        return std::size_t(r.x) +
               std::size_t(mSizeInRegions.x) *
                   (std::size_t(r.y) + std::size_t(mSizeInRegions.y) * std::size_t(r.z));
    }
    // The cell's index within its region's page (x fastest), as the GPU computes it.
    static int pageLocal(glm::ivec3 cell) {
        const glm::ivec3 l = cell & (kRegionCells - 1);
        return l.x + kRegionCells * (l.y + kRegionCells * l.z);
    }

    std::uint32_t get(glm::ivec3 cell) const {
        return mPages[mTable[regionIndex(cell)]]->cells[pageLocal(cell)];
    }
    // Sets a cell (inside the grid); returns the value it held.
    std::uint32_t set(glm::ivec3 cell, std::uint32_t value);
    // The cell's marks (BrickGrid's dirty/touched bits). Only for a cell on a page of its own:
    // a cell that is or was non-empty since the last releaseEmptyPages().
    std::uint8_t& marks(glm::ivec3 cell);

    // Whether the region holding `cell` has a page of its own (else every cell of it is empty).
    bool regionHasPage(glm::ivec3 cell) const { return mTable[regionIndex(cell)] != kEmptyPage; }
    // Pages without a non-empty cell go back to the free list; their regions map to page 0.
    void releaseEmptyPages();

    // The region table (page per region, x fastest) and the pages, for the GPU mirror.
    std::span<const std::uint32_t> table() const { return mTable; }
    std::uint32_t pageCount() const { return static_cast<std::uint32_t>(mPages.size()); }
    const std::uint32_t* pageCells(std::uint32_t page) const { return mPages[page]->cells; }
    std::uint32_t livePages() const {
        return pageCount() - 1u - static_cast<std::uint32_t>(mFreePages.size());
    }
    // f(value) for every cell of every page in use (empty cells too, in no particular order):
    // the cells of regions on page 0 are all empty.
    template <typename F>
    void forEachLiveCell(F&& f) const {
        for (std::uint32_t page = 1; page < mPages.size(); ++page) {
            const Page& p = *mPages[page];
            if (mTable[p.region] != page) continue;  // free
            for (std::uint32_t v : p.cells) f(v);
        }
    }
    // Region indices whose table entry changed since the last clearRegionChanges().
    std::span<const std::uint32_t> changedRegions() const { return mChangedRegions; }
    void clearRegionChanges();

    std::size_t bytes() const;  // table, pages (live and free) and free list

private:
    struct Page {
        std::uint32_t cells[kPageCells];
        std::uint8_t marks[kPageCells];
        std::uint32_t nonEmpty = 0;
        std::uint32_t region = 0;  // the region it belongs to (while live)
    };
    void setTable(std::size_t region, std::uint32_t page);

    glm::ivec3 mSizeInRegions;
    std::vector<std::uint32_t> mTable;
    std::vector<std::unique_ptr<Page>> mPages;  // [0]: the shared empty page
    std::vector<std::uint32_t> mFreePages;
    std::vector<std::uint32_t> mChangedRegions;
    std::vector<std::uint8_t> mRegionChanged;
};

}  // namespace engine::world
