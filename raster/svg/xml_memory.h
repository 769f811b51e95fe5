// Counting the memory pugixml takes while it parses a document, so that a large SVG's tree counts
// against the render's memory budget (--max-memory) like its canvas and layers do.
//
// pugixml allocates through two global functions (pugi::set_memory_management_functions). The ones
// installed here are malloc and free themselves plus a count: each allocation adds its block's size to
// the counter of the parse running on this thread, if any, and fails (pugixml then reports "out of
// memory") once that count passes the parse's bound. Because the blocks are plain malloc blocks, memory
// allocated before the functions were installed, or on threads that are not parsing, is freed correctly
// as well. Frees are not subtracted: a parse rarely frees, so the count is its peak, rounded up.
#pragma once

#include <cstddef>
#include <cstdint>

namespace curvescan::svg::detail {

/// pugixml's allocation function once a count was made (malloc, counted; exposed for the class below).
void* counted_allocate(std::size_t size) noexcept;

/// While alive, counts pugixml's allocations on this thread against `max_bytes`.
class XmlMemoryCount {
 public:
  explicit XmlMemoryCount(std::int64_t max_bytes) noexcept;
  ~XmlMemoryCount();
  XmlMemoryCount(const XmlMemoryCount&) = delete;
  XmlMemoryCount& operator=(const XmlMemoryCount&) = delete;

  /// Bytes allocated so far (malloc's usable sizes).
  [[nodiscard]] std::int64_t bytes() const noexcept { return bytes_; }
  /// True when an allocation was refused because the count would pass the bound.
  [[nodiscard]] bool exceeded() const noexcept { return exceeded_; }

 private:
  friend void* counted_allocate(std::size_t size) noexcept;
  std::int64_t max_bytes_;
  std::int64_t bytes_ = 0;
  bool exceeded_ = false;
  XmlMemoryCount* outer_;
};

}  // namespace curvescan::svg::detail
