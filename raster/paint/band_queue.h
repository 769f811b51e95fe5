// BandQueue: the bands of successive fills drawn on a pool of threads, giving every pixel exactly the
// blends it gets when the fills are drawn one after another.
//
// Canvas::fill cuts each fill at fixed row lines of the canvas (every Canvas::kBandRows rows) into bands;
// each band is a job that writes only its own rows. A job may start once no job submitted before it,
// still waiting or running, shares a row with it. Two jobs on disjoint rows write disjoint pixels; jobs
// on a common row run in submission order. So each pixel receives the same blends in the same order as
// in a serial render, and the image is byte-identical whatever the thread count or the scheduling. While
// the worker threads draw, the caller's thread goes on to flatten and stroke the next paths (and helps
// drawing when the queue is full), so path preparation overlaps rasterization.
//
// The threads are started once, by the first submit() that asks for them, and live as long as the queue
// (one canvas, one render): no thread is created per fill.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/rasterizer.h"
#include "gradient_table_cache.h"

namespace curvescan::detail {

/// What the bands of one fill share (the arguments of rasterize_with_paint besides the rasterizer).
struct BandPaint {
  FillRule rule = FillRule::kNonZero;
  Antialias antialias = Antialias::kExact;
  Paint paint;
  Affine transform = Affine::identity();
  Image* target = nullptr;  // the canvas image or its innermost layer: stable while jobs are queued
  int origin_x = 0, origin_y = 0;
  const ClipMask* mask = nullptr;                     // stable while jobs are queued
  std::shared_ptr<GradientTableSlot> gradient_table;  // rasterize_with_paint's, shared by the bands
};

/// One band of one fill: the edges of rows [row0, row1) and how to paint them.
struct BandJob {
  int row0 = 0, row1 = 0;
  Rasterizer rasterizer;
  std::shared_ptr<const BandPaint> paint;
};

/// Rasterizes and composites one band (rasterize_with_paint).
void draw_band(BandJob& job);

class BandQueue {
 public:
  /// At most this many jobs wait before submit() makes its caller draw too.
  static constexpr std::size_t kMaxWaitingJobs = 64;

  BandQueue() = default;
  BandQueue(const BandQueue&) = delete;
  BandQueue& operator=(const BandQueue&) = delete;
  /// Draws what is queued and stops the threads.
  ~BandQueue();

  /// A rasterizer for a new band: one whose band was drawn (its buffers are reused), or a new one.
  [[nodiscard]] Rasterizer take_spare();
  /// Queues `jobs` (moved out, in order) to be drawn on `threads` threads, the caller's included; starts
  /// the worker threads the first time (again only if `threads` changes). Before returning, the caller
  /// draws queued jobs itself while more than kMaxWaitingJobs wait or the queued jobs hold more than
  /// `max_queued_edges` edges. A job's exception is kept and rethrown by finish().
  void submit(std::vector<BandJob>& jobs, int threads, std::size_t max_queued_edges);
  /// Draws every queued job (the caller's thread helping) and waits for all of them; then rethrows the
  /// first exception a job threw since the last finish(), if any.
  void finish();
  /// finish() that drops a job's exception (for destructors and moves).
  void finish_quietly() noexcept;

 private:
  struct Slot {
    BandJob job;
    std::size_t edges = 0;  // job.rasterizer.edge_count() when queued
    enum class State : std::uint8_t { kWaiting, kRunning, kDone } state = State::kWaiting;
  };
  /// The first waiting job whose rows no earlier unfinished job shares, marked running; or null.
  /// Called with mutex_ held.
  Slot* pick();
  /// Runs `slot`'s job without the lock, then marks it done and recycles its rasterizer. `lock` holds
  /// mutex_ on entry and on return.
  void run(Slot& slot, std::unique_lock<std::mutex>& lock);
  void worker_loop();
  void stop_workers() noexcept;
  /// Draws queued jobs on the calling thread, or waits for the workers, until `done()` (mutex_ held).
  template <typename Done>
  void help_until(std::unique_lock<std::mutex>& lock, Done done);

  std::mutex mutex_;
  std::condition_variable changed_;  // a job was queued or finished, or the workers are stopping
  std::deque<Slot> slots_;           // submission order; finished jobs leave from the front
  std::size_t waiting_ = 0;          // slots in state kWaiting
  std::size_t queued_edges_ = 0;     // edges held by unfinished jobs
  std::vector<Rasterizer> spares_;
  std::exception_ptr failure_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace curvescan::detail
