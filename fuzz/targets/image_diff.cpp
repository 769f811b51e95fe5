// Fuzz target image_diff: two images and the diff options through compare_images (image_diff.h), and the
// one-sentence summary of the result.
//
// Layout of the bytes: 1 byte mode, then the options (metric, anti-aliasing, per-pixel threshold,
// tolerances, up to 3 ignore regions with coordinates that may be hostile ints), then the two images:
//   mode bit 0 clear: two PNG files, a 4-byte little-endian length of the first, then the first, then the
//                     rest is the second (read by read_png, as `curvescan diff` reads them);
//   mode bit 0 set:   two raw images of 1..16 x 1..16 pixels, each width, height and RGBA bytes (so that
//                     the comparison code sees many pixel patterns without a PNG decode each).
// Mode bit 1 makes the second image the first one's copy with a few bytes changed, so that the
// "same size" paths (the anti-aliasing detector, the diff image) are reached often.
#include <cstring>
#include <optional>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"
#include "fuzz_input.h"
#include "fuzz_targets.h"
#include "memory_file.h"

namespace curvescan::fuzz {
namespace {

std::optional<Image> read_png_bytes(std::span<const std::uint8_t> bytes) {
  const MemoryFile file(bytes.data(), bytes.size());
  if (file.path().empty()) return std::nullopt;
  Result<Image> image = read_png(file.path());
  if (!image) return std::nullopt;
  return std::move(*image);
}

Image raw_image(FuzzInput& input) {
  const int width = 1 + input.choice(16);
  const int height = 1 + input.choice(16);
  Image image(width, height);
  for (Rgba8& pixel : image.pixels()) {
    // Premultiplied: a channel above alpha is not a valid pixel, but a comparison must not care.
    pixel = Rgba8{input.byte(), input.byte(), input.byte(), input.byte()};
  }
  return image;
}

int coordinate(FuzzInput& input) noexcept {
  const std::uint8_t selector = input.byte();
  if (selector < 240) return static_cast<int>(selector) - 20;
  constexpr int kHostile[] = {INT32_MIN, INT32_MAX, INT32_MIN + 1, INT32_MAX - 1, -65536, 65536, 0, -1};
  return kHostile[(selector - 240) % 8];
}

DiffOptions diff_options(FuzzInput& input) {
  DiffOptions options;
  const std::uint8_t bits = input.byte();
  options.metric = (bits & 1) != 0 ? PixelMetric::kPerChannel : PixelMetric::kPerceptual;
  options.ignore_antialiasing = (bits & 2) != 0;
  options.make_diff_image = (bits & 4) == 0;
  options.yiq_threshold = input.number(0.1);
  options.channel_tolerance = static_cast<int>(input.byte()) - 8;  // -8..247: out of range at the low end
  if ((bits & 8) != 0) options.max_different_pixels = input.byte();
  if ((bits & 16) != 0) options.max_different_percent = input.number(1.0);
  const int regions = input.choice(4);
  for (int i = 0; i < regions; ++i) {
    options.ignore_regions.push_back(
        PixelBox{coordinate(input), coordinate(input), coordinate(input), coordinate(input)});
  }
  return options;
}

}  // namespace

int fuzz_image_diff(const std::uint8_t* data, std::size_t size) {
  FuzzInput input(data, size);
  const std::uint8_t mode = input.byte();
  const DiffOptions options = diff_options(input);

  std::optional<Image> expected, actual;
  if ((mode & 1) != 0) {
    expected = raw_image(input);
    actual = raw_image(input);
  } else {
    const std::span<const std::uint8_t> length_bytes = input.bytes(4);
    std::uint32_t first_length = 0;
    for (std::size_t i = 0; i < length_bytes.size(); ++i) first_length |= std::uint32_t{length_bytes[i]} << (8 * i);
    expected = read_png_bytes(input.bytes(first_length));
    actual = read_png_bytes(input.bytes(input.remaining()));
  }
  if (!expected) return 0;
  if ((mode & 2) != 0 || !actual) {
    // A copy of the first image with a few bytes changed, from the remaining input.
    actual = *expected;
    auto* bytes = reinterpret_cast<std::uint8_t*>(actual->pixels().data());  // Rgba8 is 4 bytes
    const std::size_t count = actual->pixels().size() * sizeof(Rgba8);
    for (int i = 0; i < 8 && !input.empty(); ++i) bytes[input.byte() % count] = input.byte();
  }

  const Result<ImageComparison> comparison = compare_images(*expected, *actual, options);
  if (comparison) (void)describe_comparison(*comparison);
  return 0;
}

}  // namespace curvescan::fuzz
