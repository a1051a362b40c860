#include "world/paged_top_grid.h"

#include <algorithm>

#include "core/check.h"

namespace engine::world {

PagedTopGrid::PagedTopGrid(glm::ivec3 sizeInCells) {
    mSizeInRegions = regionCount(sizeInCells);
    const std::size_t regions =
        std::size_t(mSizeInRegions.x) * mSizeInRegions.y * std::size_t(mSizeInRegions.z);
    mTable.assign(regions, kEmptyPage);
    mRegionChanged.assign(regions, 0);
    mPages.push_back(std::make_unique<Page>());
    std::fill(std::begin(mPages[0]->cells), std::end(mPages[0]->cells), shared::CELL_EMPTY);
    std::fill(std::begin(mPages[0]->marks), std::end(mPages[0]->marks), 0);
}

PagedTopGrid::PagedTopGrid(const PagedTopGrid& other)
    : mSizeInRegions(other.mSizeInRegions),
      mTable(other.mTable),
      mFreePages(other.mFreePages),
      mChangedRegions(other.mChangedRegions),
      mRegionChanged(other.mRegionChanged) {
    mPages.reserve(other.mPages.size());
    for (const auto& page : other.mPages) mPages.push_back(std::make_unique<Page>(*page));
}

PagedTopGrid& PagedTopGrid::operator=(const PagedTopGrid& other) {
    if (this != &other) *this = PagedTopGrid(other);
    return *this;
}

std::uint32_t PagedTopGrid::set(glm::ivec3 cell, std::uint32_t value) {
    const std::size_t region = regionIndex(cell);
    std::uint32_t page = mTable[region];
    const int local = pageLocal(cell);
    const std::uint32_t old = mPages[page]->cells[local];
    if (old == value) return old;
    if (page == kEmptyPage) {
        // old is empty and value is not: the region needs a page of its own.
        if (!mFreePages.empty()) {
            page = mFreePages.back();
            mFreePages.pop_back();
        } else {
            CHECK_MSG(mPages.size() < 0xFFFFFFF0u, "top-grid pages exhausted");
            mPages.push_back(std::make_unique<Page>());
            page = static_cast<std::uint32_t>(mPages.size() - 1);
        }
        Page& fresh = *mPages[page];
        std::fill(std::begin(fresh.cells), std::end(fresh.cells), shared::CELL_EMPTY);
        std::fill(std::begin(fresh.marks), std::end(fresh.marks), 0);
        fresh.nonEmpty = 0;
        fresh.region = static_cast<std::uint32_t>(region);
        setTable(region, page);
    }
    Page& p = *mPages[page];
    p.cells[local] = value;
    if (old == shared::CELL_EMPTY) ++p.nonEmpty;
    if (value == shared::CELL_EMPTY) --p.nonEmpty;
    return old;
}

std::uint8_t& PagedTopGrid::marks(glm::ivec3 cell) {
    const std::uint32_t page = mTable[regionIndex(cell)];
    CHECK_MSG(page != kEmptyPage, "marks of a cell on the shared empty page");
    return mPages[page]->marks[pageLocal(cell)];
}

void PagedTopGrid::releaseEmptyPages() {
    for (std::uint32_t page = 1; page < mPages.size(); ++page) {
        Page& p = *mPages[page];
        if (p.nonEmpty != 0 || mTable[p.region] != page) continue;
        setTable(p.region, kEmptyPage);
        mFreePages.push_back(page);
    }
}

void PagedTopGrid::setTable(std::size_t region, std::uint32_t page) {
    mTable[region] = page;
    if (!mRegionChanged[region]) {
        mRegionChanged[region] = 1;
        mChangedRegions.push_back(static_cast<std::uint32_t>(region));
    }
}

void PagedTopGrid::clearRegionChanges() {
    for (std::uint32_t r : mChangedRegions) mRegionChanged[r] = 0;
    mChangedRegions.clear();
}

std::size_t PagedTopGrid::bytes() const {
    return mTable.size() * sizeof(std::uint32_t) + mRegionChanged.size() +
           mPages.size() * sizeof(Page) +
           (mFreePages.size() + mChangedRegions.size()) * sizeof(std::uint32_t);
}

}  // namespace engine::world
