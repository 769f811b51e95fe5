// Running a deeply recursive step (the SVG renderer walks the element tree recursively, one level per
// nesting level) on a thread whose stack is sized for the nesting limit, so that raising --max-depth
// cannot overflow the 8 MiB main stack (measured: ~3 KiB per level in a release build, several times
// that under AddressSanitizer).
#pragma once

#include <pthread.h>

#include <cstddef>
#include <exception>
#include <optional>
#include <utility>

namespace curvescan::cli {

/// Calls `work()` on a new thread with a `stack_bytes` stack and returns its result; exceptions are
/// rethrown here. When no such thread can be made, `work()` runs on the calling thread.
template <class Work>
auto run_on_large_stack(std::size_t stack_bytes, Work&& work) -> decltype(work()) {
  using Value = decltype(work());
  struct Call {
    Work* work;
    std::optional<Value> value;
    std::exception_ptr error;
    static void* run(void* argument) {
      Call& call = *static_cast<Call*>(argument);
      try {
        call.value.emplace((*call.work)());
      } catch (...) {
        call.error = std::current_exception();
      }
      return nullptr;
    }
  };
  Call call{&work, std::nullopt, nullptr};
  pthread_attr_t attributes;
  if (pthread_attr_init(&attributes) != 0) return work();
  pthread_t thread;
  const bool started = pthread_attr_setstacksize(&attributes, stack_bytes) == 0 &&
                       pthread_create(&thread, &attributes, &Call::run, &call) == 0;
  pthread_attr_destroy(&attributes);
  if (!started) return work();
  pthread_join(thread, nullptr);
  if (call.error) std::rethrow_exception(call.error);
  return std::move(*call.value);
}

}  // namespace curvescan::cli
