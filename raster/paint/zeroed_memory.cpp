// Zeroed memory for pixels (zeroed_memory.h).
#include "curvescan/raster/zeroed_memory.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace curvescan {
namespace {

#if defined(__linux__) && defined(MADV_HUGEPAGE)
constexpr std::size_t kHugePage = std::size_t{2} << 20;

// A mapping of `bytes` rounded up to whole huge pages, starting on a huge-page boundary: the mapping is
// made one huge page longer, and the ends beyond the aligned part are unmapped. Fresh anonymous memory is
// zero. nullptr when the system refuses.
void* map_huge(std::size_t bytes) noexcept {
  const std::size_t size = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t end = start + size + kHugePage, used_end = aligned + size;
  if (end > used_end) munmap(reinterpret_cast<void*>(used_end), end - used_end);
  void* memory = reinterpret_cast<void*>(aligned);
  madvise(memory, size, MADV_HUGEPAGE);  // a hint: without huge pages the mapping still works
  return memory;
}

void unmap_huge(void* memory, std::size_t bytes) noexcept {
  const std::size_t size = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  munmap(memory, size);
}

// Which blocks were mapped (rather than from calloc) is decided by size alone, so release needs no record.
bool mapped(std::size_t bytes) noexcept {
  return bytes >= kHugeBlockBytes;
}
#endif

}  // namespace

std::size_t zeroed_block_rounding_bytes() noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  return kHugePage;
#else
  return 0;
#endif
}

std::size_t zeroed_block_bytes(std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (mapped(bytes) && bytes <= SIZE_MAX - kHugePage) return (bytes + kHugePage - 1) / kHugePage * kHugePage;
#endif
  return bytes;
}

void* allocate_zeroed(std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (mapped(bytes)) {
    if (void* memory = map_huge(bytes)) return memory;
    throw std::bad_alloc();
  }
#endif
  void* memory = std::calloc(bytes == 0 ? 1 : bytes, 1);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

void release_zeroed(void* memory, std::size_t bytes) noexcept {
  if (memory == nullptr) return;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (mapped(bytes)) {
    unmap_huge(memory, bytes);
    return;
  }
#endif
  std::free(memory);
}

}  // namespace curvescan
