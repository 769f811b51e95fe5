// Memory for pixels: zero when handed out, and cheap to fault in. Image's pixels (image.h) and the SVG
// filters' float images both live in it.
//
// An image of a large canvas or filter region is many megabytes, made and dropped once per layer, mask or
// filter primitive. Most of a drop shadow's time used to be the operating system handing out fresh 4 KiB
// pages (a fault, a clear and the bookkeeping for each), not the arithmetic. Two things keep that small:
//  - memory comes from the system already zero (calloc, or a fresh anonymous mapping), so making an image
//    costs no pass over it, and pages nothing writes are never touched; the pages of a canvas are then
//    cleared by the kernel when first written, on the thread that writes them (Canvas::set_threads: the
//    bands clear their own rows, in parallel);
//  - on Linux, a block of at least kHugeBlockBytes is its own mapping, aligned to 2 MiB and marked with
//    madvise(MADV_HUGEPAGE), so that where the system allows transparent huge pages one fault brings in
//    2 MiB instead of 4 KiB. Elsewhere, or for smaller blocks, calloc serves.
// A mapped block is rounded up to whole huge pages, which, faulted in as huge pages, are resident: memory
// budgets count a block as zeroed_block_bytes(), not its bare size.
#pragma once

#include <cstddef>
#include <new>
#include <utility>

namespace curvescan {

/// Blocks from this size up are mapped on their own (see above).
inline constexpr std::size_t kHugeBlockBytes = std::size_t{2} << 20;

/// The most memory a block of any size can hold beyond its own bytes: up to one huge page less a byte
/// where blocks are mapped in huge pages, nothing where they all come from calloc.
[[nodiscard]] std::size_t zeroed_block_rounding_bytes() noexcept;

/// The memory a block of `bytes` takes: `bytes`, rounded up to whole huge pages when it is mapped.
[[nodiscard]] std::size_t zeroed_block_bytes(std::size_t bytes) noexcept;

/// `bytes` of zero memory (never null: throws std::bad_alloc), and its release.
[[nodiscard]] void* allocate_zeroed(std::size_t bytes);
void release_zeroed(void* memory, std::size_t bytes) noexcept;

/// An allocator whose memory starts zero and whose value-initialised elements are not written, so that
/// a vector of n elements costs no pass over its memory. For element types whose zero bytes are their
/// value-initialised state and which are implicit-lifetime types (arithmetic types, aggregates of them
/// such as Rgba8): such objects exist in the allocated memory without being constructed (C++20
/// [intro.object]), and every byte is already 0. A vector using it keeps its size for its life: growing
/// it again after shrinking would leave old values in the regrown elements instead of zeros.
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
  /// Value-initialisation (vector(n), resize(n)): the memory is zero already.
  template <class U>
  void construct(U*) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const ZeroedAllocator<U>&) const noexcept {
    return true;
  }
};

}  // namespace curvescan
