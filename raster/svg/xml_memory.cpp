// Counting pugixml's allocations during a parse (xml_memory.h).
#include "xml_memory.h"

#include <malloc.h>

#include <cstdlib>
#include <mutex>

#include <pugixml.hpp>

namespace curvescan::svg::detail {
namespace {

thread_local XmlMemoryCount* current_count = nullptr;

void counted_free(void* block) noexcept { std::free(block); }

void install_counting_functions() {
  static std::once_flag installed;
  std::call_once(installed, [] { pugi::set_memory_management_functions(counted_allocate, counted_free); });
}

}  // namespace

void* counted_allocate(std::size_t size) noexcept {
  XmlMemoryCount* count = current_count;
  if (count != nullptr && count->bytes_ + static_cast<std::int64_t>(size) > count->max_bytes_) {
    count->exceeded_ = true;
    return nullptr;
  }
  void* block = std::malloc(size);
  if (block != nullptr && count != nullptr) count->bytes_ += static_cast<std::int64_t>(malloc_usable_size(block));
  return block;
}

XmlMemoryCount::XmlMemoryCount(std::int64_t max_bytes) noexcept : max_bytes_(max_bytes), outer_(current_count) {
  install_counting_functions();
  current_count = this;
}

XmlMemoryCount::~XmlMemoryCount() { current_count = outer_; }

}  // namespace curvescan::svg::detail
