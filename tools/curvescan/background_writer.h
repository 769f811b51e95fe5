// Writing a batch's output files on threads of their own, so that rendering does not wait for the disk.
//
// Every output is written safely (curvescan/raster/file_io.h): a temporary file, its data flushed to the
// device with fsync, then renamed over the target. The fsync waits for the device: on an ordinary disk
// it was about half of a one-thread batch's wall time while using almost no CPU. Here the render threads
// encode each PNG and hand the bytes over; a few writer threads do the safe writes, several fsyncs in
// flight at once (a journaling file system commits them together). Each file is still durable before its
// name appears, and an interrupted batch leaves only temporaries that the signal handler removes.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "curvescan/status.h"

namespace curvescan::cli {

class BackgroundWriter {
 public:
  /// `threads` writer threads; write() waits while the queued bytes exceed `max_queued_bytes`, so the
  /// renders cannot run ahead of the disk without bound.
  BackgroundWriter(unsigned threads, std::size_t max_queued_bytes);
  BackgroundWriter(const BackgroundWriter&) = delete;
  BackgroundWriter& operator=(const BackgroundWriter&) = delete;
  /// Writes what is queued, then stops the threads.
  ~BackgroundWriter();

  /// Queues `bytes` for `path` (write_output_file). `done` is called with the result on a writer thread.
  void write(std::string path, std::vector<std::uint8_t> bytes, std::function<void(const Status&)> done);

 private:
  struct Job {
    std::string path;
    std::vector<std::uint8_t> bytes;
    std::function<void(const Status&)> done;
  };
  void run();

  std::mutex mutex_;
  std::condition_variable job_queued_, room_freed_;
  std::deque<Job> queue_;
  std::size_t queued_bytes_ = 0;
  std::size_t max_queued_bytes_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace curvescan::cli
