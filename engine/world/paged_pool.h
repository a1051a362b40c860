// PagedPool: a growable array stored in fixed pages of 2^PageShift elements. Growing adds a page
// and never moves what is there, so a pool of gigabytes grows without the doubling vector's
// transient (old and new storage at once: 3x the pool while a large world generates), and
// element addresses stay stable.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace engine::world {

template <typename T, unsigned PageShift>
class PagedPool {
public:
    static constexpr std::size_t kPageSize = std::size_t(1) << PageShift;

    PagedPool() = default;
    PagedPool(PagedPool&&) noexcept = default;
    PagedPool& operator=(PagedPool&&) noexcept = default;
    PagedPool(const PagedPool& other) : mSize(other.mSize) {
        mPages.reserve(other.mPages.size());
        for (const auto& page : other.mPages) {
            mPages.push_back(std::make_unique<T[]>(kPageSize));
            std::copy(page.get(), page.get() + kPageSize, mPages.back().get());
        }
    }
    PagedPool& operator=(const PagedPool& other) {
        if (this != &other) *this = PagedPool(other);
        return *this;
    }

    std::size_t size() const { return mSize; }
    T& operator[](std::size_t i) { return mPages[i >> PageShift][i & (kPageSize - 1)]; }
    const T& operator[](std::size_t i) const { return mPages[i >> PageShift][i & (kPageSize - 1)]; }

    // Appends a value-initialised element.
    void emplace_back() {
        if (mSize == mPages.size() * kPageSize)
            mPages.push_back(std::make_unique<T[]>(kPageSize));
        else
            (*this)[mSize] = T{};
        ++mSize;
    }
    void reservePages(std::size_t elements) {
        mPages.reserve((elements + kPageSize - 1) / kPageSize);
    }

private:
    std::vector<std::unique_ptr<T[]>> mPages;
    std::size_t mSize = 0;
};

}  // namespace engine::world
