// GradientTableSlot and GradientTableCache: one pad-gradient colour table (gradient_color_table.h) per
// gradient, shared by every band of a fill and by the later fills of the same gradient on a canvas.
//
// Why. The table is 65 539 walker evaluations, about the cost of shading as many pixels. A fill is cut
// into bands of Canvas::kBandRows rows (drawn by separate compositors, possibly on several threads), and an
// application draws the same gradient paint again and again (every frame, every shape of a chart). When each
// compositor built its own table, a 512² fill built four (one per band), every frame: 36 % of the time of a
// full-canvas linear gradient fill (perf). Now the first compositor that needs the table builds it in the
// slot and every other one reads it.
//
// Rent or buy. The slot counts the pixels its gradient has shaded with the walker, over every fill that
// used the slot; the table is built once that count reaches GradientSpanCompositor::kTableAfterPixels, so a
// gradient that only ever paints small shapes never pays for a table, and one that paints many pixels pays
// for it once.
//
// Threads. The count is atomic; the build happens under the slot's mutex (a compositor arriving meanwhile
// waits instead of building a second table) and the finished table is published through an atomic pointer,
// read without the lock afterwards. A table is immutable once published.
//
// Memory. A canvas keeps the slots of at most kMaxSlots gradients (about 1 MiB of tables at most), counted
// in Canvas::memory_bytes() against the render's budget. A slot still used by queued bands is never
// evicted; when every slot is in use (fills of more than kMaxSlots gradients queued at once), a fill gets
// no slot and its bands shade with the walker, the same colours: a slot outside the cache would be memory
// the budget does not see.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <new>
#include <optional>

#include "curvescan/raster/gradient.h"
#include "gradient_color_table.h"
#include "gradient_walker.h"

namespace curvescan::detail {

class GradientTableSlot {
 public:
  /// The table when it has been built, or null.
  [[nodiscard]] const PadColorTable* table() const noexcept {
    return published_.load(std::memory_order_acquire);
  }

  /// Counts `pixels` more shaded with the walker; returns the count before them (every fill of the slot).
  long add_shaded(long pixels) noexcept { return shaded_.fetch_add(pixels, std::memory_order_relaxed); }

  /// The table, built now with `walker` (of this slot's gradient) if no compositor built it yet. Null
  /// when memory for it could not be allocated (the walker then gives the same colours).
  const PadColorTable* build(GradientWalker& walker) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const PadColorTable* ready = table()) return ready;
    if (failed_) return nullptr;
    try {
      table_.emplace(walker);
    } catch (const std::bad_alloc&) {
      failed_ = true;
      return nullptr;
    }
    published_.store(&*table_, std::memory_order_release);
    return &*table_;
  }

 private:
  std::mutex mutex_;
  std::optional<PadColorTable> table_;  // written once, under mutex_
  bool failed_ = false;                 // under mutex_
  std::atomic<const PadColorTable*> published_{nullptr};
  std::atomic<long> shaded_{0};
};

/// A canvas's slots, by gradient (see above). Used by the thread that calls Canvas::fill only.
class GradientTableCache {
 public:
  static constexpr std::size_t kMaxSlots = 4;

  /// The slot of `shader` (pad spread; null for other spreads, whose colours are not tabled). A new slot
  /// is created only when `room_for_table` (the render's memory budget has PadColorTable::kBytes left)
  /// and an entry is free or held by no queued band; otherwise null.
  [[nodiscard]] std::shared_ptr<GradientTableSlot> slot_for(
      const std::shared_ptr<const GradientShader>& shader, bool room_for_table) {
    if (shader == nullptr || shader->spread() != SpreadMethod::kPad) return nullptr;
    for (Entry& entry : entries_) {
      if (entry.shader == shader) return entry.slot;
    }
    if (!room_for_table) return nullptr;
    for (Entry& entry : entries_) {
      // Free, or held by no queued band: the entry's table may go.
      if (entry.slot == nullptr || entry.slot.use_count() == 1) {
        entry = {shader, std::make_shared<GradientTableSlot>()};
        return entry.slot;
      }
    }
    return nullptr;  // every entry is in use by queued bands
  }

  /// Memory of the tables built in the kept slots.
  [[nodiscard]] std::int64_t memory_bytes() const noexcept {
    std::int64_t bytes = 0;
    for (const Entry& entry : entries_) {
      if (entry.slot != nullptr && entry.slot->table() != nullptr) bytes += PadColorTable::kBytes;
    }
    return bytes;
  }

 private:
  struct Entry {
    std::shared_ptr<const GradientShader> shader;  // kept alive, so that no other shader reuses its address
    std::shared_ptr<GradientTableSlot> slot;
  };
  std::array<Entry, kMaxSlots> entries_{};
};

}  // namespace curvescan::detail
