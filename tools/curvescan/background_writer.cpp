// Writing output files on writer threads (background_writer.h).
#include "background_writer.h"

#include <string_view>
#include <utility>

#include "curvescan/raster/file_io.h"

namespace curvescan::cli {

BackgroundWriter::BackgroundWriter(unsigned threads, std::size_t max_queued_bytes)
    : max_queued_bytes_(max_queued_bytes) {
  for (unsigned i = 0; i < threads; ++i) threads_.emplace_back([this] { run(); });
}

BackgroundWriter::~BackgroundWriter() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  job_queued_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void BackgroundWriter::write(std::string path, std::vector<std::uint8_t> bytes,
                             std::function<void(const Status&)> done) {
  std::unique_lock lock(mutex_);
  // One file larger than the bound still goes through, alone.
  room_freed_.wait(lock,
                   [&] { return queued_bytes_ == 0 || queued_bytes_ + bytes.size() <= max_queued_bytes_; });
  queued_bytes_ += bytes.size();
  queue_.push_back(Job{std::move(path), std::move(bytes), std::move(done)});
  lock.unlock();
  job_queued_.notify_one();
}

void BackgroundWriter::run() {
  while (true) {
    std::unique_lock lock(mutex_);
    job_queued_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, and nothing left to write
    Job job = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    const Status written = write_output_file(
        job.path, std::string_view(reinterpret_cast<const char*>(job.bytes.data()), job.bytes.size()));
    job.done(written);
    lock.lock();
    queued_bytes_ -= job.bytes.size();
    lock.unlock();
    room_freed_.notify_all();
  }
}

}  // namespace curvescan::cli
