#pragma once
// Large arrays read at scattered places (the DEM's heights, the min/max
// pyramid) in transparent huge pages where the kernel offers them: a HAT/HOT
// or line-of-sight query touches a few cache lines anywhere in 64 MB of
// heights, and with 4 KB pages each of those is also a TLB miss, a page walk
// that (in a VM, through nested page tables) costs more than the cache miss
// itself. With 2 MB pages the whole array fits the TLB. A hint only: where
// huge pages are off (or not Linux) nothing changes.

#include <cstddef>
#include <vector>

namespace ig::terrain {

// Asks the kernel to back [data, data + bytes) with huge pages when it is
// first touched (madvise MADV_HUGEPAGE on the whole 2 MB pages inside).
// Returns whether the advice was taken.
bool advise_huge_pages(const void* data, std::size_t bytes);

// v.reserve(n), its storage advised before anything touches it, so the
// page faults that follow (resize, assign, a reader writing into it) bring
// in huge pages.
template <typename T>
void reserve_in_huge_pages(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace ig::terrain
