// BandQueue (band_queue.h): ordered band jobs on a persistent pool of threads.
#include "band_queue.h"

#include <algorithm>
#include <utility>

#include "paint_dispatch.h"

namespace curvescan::detail {
namespace {

// Spare rasterizers kept for reuse; beyond this their buffers are freed.
constexpr std::size_t kMaxSpares = 2 * BandQueue::kMaxWaitingJobs;

}  // namespace

void draw_band(BandJob& job) {
  const BandPaint& p = *job.paint;
  rasterize_with_paint(job.rasterizer, p.rule, p.antialias, p.paint, p.transform, *p.target, p.origin_x,
                       p.origin_y, p.mask, p.gradient_table);
}

BandQueue::~BandQueue() {
  finish_quietly();
  stop_workers();
}

Rasterizer BandQueue::take_spare() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (spares_.empty()) return Rasterizer{};
  Rasterizer spare = std::move(spares_.back());
  spares_.pop_back();
  return spare;
}

BandQueue::Slot* BandQueue::pick() {
  if (waiting_ == 0) return nullptr;
  // Rows of earlier unfinished jobs, as [row0, row1) intervals; slots_ holds at most a few hundred jobs.
  thread_local std::vector<std::pair<int, int>> busy;
  busy.clear();
  for (Slot& slot : slots_) {
    if (slot.state == Slot::State::kDone) continue;
    const int row0 = slot.job.row0, row1 = slot.job.row1;
    if (slot.state == Slot::State::kWaiting && std::none_of(busy.begin(), busy.end(), [&](const auto& rows) {
          return rows.first < row1 && row0 < rows.second;
        })) {
      slot.state = Slot::State::kRunning;
      --waiting_;
      return &slot;
    }
    busy.emplace_back(row0, row1);
  }
  return nullptr;
}

void BandQueue::run(Slot& slot, std::unique_lock<std::mutex>& lock) {
  lock.unlock();
  std::exception_ptr failure;
  try {
    draw_band(slot.job);
  } catch (...) {
    failure = std::current_exception();
  }
  lock.lock();
  if (failure && !failure_) failure_ = failure;
  slot.state = Slot::State::kDone;
  queued_edges_ -= slot.edges;
  while (!slots_.empty() && slots_.front().state == Slot::State::kDone) {
    if (spares_.size() < kMaxSpares) spares_.push_back(std::move(slots_.front().job.rasterizer));
    slots_.pop_front();
  }
  changed_.notify_all();
}

void BandQueue::worker_loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    Slot* slot = nullptr;
    changed_.wait(lock, [&] { return stopping_ || (slot = pick()) != nullptr; });
    if (slot == nullptr) return;  // stopping, nothing runnable
    run(*slot, lock);
  }
}

template <typename Done>
void BandQueue::help_until(std::unique_lock<std::mutex>& lock, Done done) {
  while (!done()) {
    if (Slot* slot = pick()) {
      run(*slot, lock);
    } else {
      changed_.wait(lock);
    }
  }
}

void BandQueue::submit(std::vector<BandJob>& jobs, int threads, std::size_t max_queued_edges) {
  const std::size_t workers = threads > 1 ? static_cast<std::size_t>(threads - 1) : 0;
  if (workers != workers_.size()) {
    finish_quietly();  // a failure stays in failure_ for the next finish()
    stop_workers();
    stopping_ = false;
    workers_.reserve(workers);
    for (std::size_t w = 0; w < workers; ++w) workers_.emplace_back([this] { worker_loop(); });
  }
  std::unique_lock<std::mutex> lock(mutex_);
  for (BandJob& job : jobs) {
    const std::size_t edges = job.rasterizer.edge_count();
    queued_edges_ += edges;
    slots_.push_back(Slot{std::move(job), edges});
    ++waiting_;
  }
  jobs.clear();
  changed_.notify_all();
  help_until(lock, [&] { return waiting_ <= kMaxWaitingJobs && queued_edges_ <= max_queued_edges; });
}

void BandQueue::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  help_until(lock, [&] { return slots_.empty(); });
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void BandQueue::finish_quietly() noexcept {
  std::unique_lock<std::mutex> lock(mutex_);
  help_until(lock, [&] { return slots_.empty(); });
}

void BandQueue::stop_workers() noexcept {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& worker : workers_) worker.join();
  workers_.clear();
}

}  // namespace curvescan::detail
