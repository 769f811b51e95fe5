// Memory for filter images: zero when handed out, and cheap to fault in.
//
// A filter image of a large region is many megabytes of floats, made and dropped once per primitive and per
// render. Most of a drop shadow's time used to be the operating system handing out fresh 4 KiB pages
// (a fault, a clear and the bookkeeping for each), not the arithmetic. Two things keep that small:
//  - memory comes from the system already zero (calloc, or a fresh anonymous mapping), so making an image
//    costs no pass over it, and pages a primitive never writes (outside its input's ink) are never
//    touched;
//  - on Linux, a block of at least kHugeBlockBytes is its own mapping, aligned to 2 MiB and marked with
//    madvise(MADV_HUGEPAGE), so that where the system allows transparent huge pages one fault brings in
//    2 MiB instead of 4 KiB. Elsewhere, or when the mapping fails, calloc serves.
#pragma once

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace curvescan::svg::detail::filter {

/// Blocks from this size up are mapped on their own (see above).
inline constexpr std::size_t kHugeBlockBytes = std::size_t{2} << 20;

/// The most memory a block of any size can hold beyond its own bytes: a mapped block is rounded up to
/// whole huge pages (which, faulted in as huge pages, are resident), so up to one huge page less a byte;
/// nothing where blocks come from calloc. Memory budgets count it once per block held at the same time.
[[nodiscard]] std::size_t block_rounding_bytes() noexcept;

/// `bytes` of zero memory (never null: throws std::bad_alloc), and its release.
[[nodiscard]] void* allocate_zeroed(std::size_t bytes);
void release_zeroed(void* memory, std::size_t bytes) noexcept;

/// An allocator whose memory starts zero and whose elements are not written on construction, so that a
/// vector of n floats costs no pass over its memory.
template <class T>
struct ZeroedAllocator {
  using value_type = T;
  ZeroedAllocator() noexcept = default;
  template <class U>
  ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor)
  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    return static_cast<T*>(allocate_zeroed(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { release_zeroed(p, n * sizeof(T)); }
  /// Value-initialization (vector(n), resize(n)) leaves the zeros as they are.
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const ZeroedAllocator<U>&) const noexcept {
    return true;
  }
};

/// The channels of a filter image, or a plane of one channel: zero when made.
using FilterPixels = std::vector<float, ZeroedAllocator<float>>;

}  // namespace curvescan::svg::detail::filter
