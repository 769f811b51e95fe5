// FuzzInput: structured values decoded from fuzz bytes, for the targets whose input is not a file format
// (raster_stroke, image_diff). Reading past the end yields zeros, so every byte string decodes to some
// scene and libFuzzer's mutations of one byte change one decision.
//
// Numbers come partly from a table of hostile values — NaN, ±Inf, ±1e30, 1e7, the smallest denormal and
// normal, ±0, values near the int and fixed-point ranges — because random bytes almost never hit them,
// and those are the values that broke peers' rasterizers (issue 8: NaN sending subdivision into an endless
// loop, huge coordinates overflowing fixed point).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace curvescan::fuzz {

inline constexpr double kHostileValues[] = {
    std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(),
    -std::numeric_limits<double>::infinity(),
    1e30,
    -1e30,
    1e7,
    -1e7,
    std::numeric_limits<double>::denorm_min(),
    -std::numeric_limits<double>::denorm_min(),
    std::numeric_limits<double>::min(),
    0.0,
    -0.0,
    std::numeric_limits<double>::max(),
    std::numeric_limits<double>::lowest(),
    std::numeric_limits<double>::epsilon(),
    2147483647.0,   // INT_MAX: the edge of int pixel coordinates
    -2147483648.0,  // INT_MIN
    8388608.0,      // 2^23: the edge of 24.8 fixed point
    1e-300,
    0.5,  // pixel centres and the half-pixel rounding boundary
};

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) noexcept : data_(data), size_(size) {}

  [[nodiscard]] bool empty() const noexcept { return offset_ >= size_; }
  [[nodiscard]] std::size_t remaining() const noexcept { return empty() ? 0 : size_ - offset_; }

  [[nodiscard]] std::uint8_t byte() noexcept { return empty() ? 0 : data_[offset_++]; }

  /// A value in [0, count) from one byte (count >= 1, at most 256).
  [[nodiscard]] int choice(int count) noexcept { return byte() % count; }

  [[nodiscard]] bool flag() noexcept { return (byte() & 1) != 0; }

  /// The next `count` bytes (fewer at the end of the input).
  [[nodiscard]] std::span<const std::uint8_t> bytes(std::size_t count) noexcept {
    const std::size_t n = count < remaining() ? count : remaining();
    const std::span<const std::uint8_t> result(data_ + offset_, n);
    offset_ += n;
    return result;
  }

  /// 8 raw bytes as a double: any bit pattern, NaN payloads and denormals included.
  [[nodiscard]] double raw_double() noexcept {
    std::uint8_t buffer[sizeof(double)] = {};
    const std::span<const std::uint8_t> source = bytes(sizeof buffer);
    if (!source.empty()) std::memcpy(buffer, source.data(), source.size());
    double value = 0.0;
    std::memcpy(&value, buffer, sizeof value);
    return value;
  }

  /// A number for a coordinate or a parameter: mostly small values on a 1/4 grid around `centre` (so that
  /// shapes land on the small canvas), sometimes a hostile value from the table, sometimes raw bits.
  [[nodiscard]] double number(double centre = 0.0) noexcept {
    const std::uint8_t selector = byte();
    if (selector < 200) return centre + (static_cast<double>(selector) - 100.0) * 0.25;
    if (selector < 250) {
      constexpr std::size_t kCount = sizeof kHostileValues / sizeof kHostileValues[0];
      return kHostileValues[static_cast<std::size_t>(selector - 200) % kCount];
    }
    return raw_double();
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t offset_ = 0;
};

}  // namespace curvescan::fuzz
