// Status and Result: how fallible curvescan calls report failure.
//
// Math in curves/ is noexcept and total; what can fail (building a curve from user data, reading a file,
// parsing) returns a Status or a Result<T> whose message is one sentence a user can act on. The CLI prints
// that sentence on one line of stderr and exits non-zero (tools/curvescan/exit_codes.h).
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace curvescan {

/// What kind of failure a Status carries; the CLI maps these to exit codes.
enum class ErrorKind {
  kInvalidArgument,  ///< the caller's data is malformed (bad knot vector, NaN coordinate, bad flag value)
  kLimitExceeded,    ///< the input asks for more than a documented limit allows
  kIoError,          ///< a file could not be read or written
  kCorruptInput,     ///< a file was read but its content is truncated or corrupt
  kUnsupported,      ///< well-formed input using a feature curvescan does not implement
};

/// An error: a kind and a one-sentence message that names the offending input.
struct Error {
  ErrorKind kind = ErrorKind::kInvalidArgument;
  std::string message;
};

/// Success, or an Error.
class [[nodiscard]] Status {
 public:
  Status() = default;  ///< success
  Status(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT(google-explicit-constructor)

  static Status ok() { return {}; }
  static Status invalid(std::string message) { return Error{ErrorKind::kInvalidArgument, std::move(message)}; }

  [[nodiscard]] bool is_ok() const noexcept { return ok_; }
  explicit operator bool() const noexcept { return ok_; }
  /// The error; only meaningful when !is_ok().
  [[nodiscard]] const Error& error() const noexcept { return error_; }

 private:
  Error error_;
  bool ok_ = true;
};

/// A value of type T, or an Error.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
  Result(Error error) : state_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool is_ok() const noexcept { return std::holds_alternative<T>(state_); }
  explicit operator bool() const noexcept { return is_ok(); }
  /// The value; only valid when is_ok().
  T& value() & { return std::get<T>(state_); }
  const T& value() const& { return std::get<T>(state_); }
  T&& value() && { return std::get<T>(std::move(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  /// The error; only valid when !is_ok().
  [[nodiscard]] const Error& error() const { return std::get<Error>(state_); }
  /// The error as a Status (success when is_ok()).
  [[nodiscard]] Status status() const { return is_ok() ? Status() : Status(error()); }

 private:
  std::variant<T, Error> state_;
};

/// Returns early from a function returning Status or Result<U> when `expr` (a Status) failed.
#define CURVESCAN_PROPAGATE(expr)                          \
  do {                                                     \
    if (::curvescan::Status status_ = (expr); !status_) {  \
      return status_.error();                              \
    }                                                      \
  } while (false)

}  // namespace curvescan
