// The zeroed memory behind Image's pixels and the SVG filters' float images (zeroed_memory.h): zero when
// handed out, and counted against the render's memory budget as the memory it really takes.
#include "curvescan/raster/zeroed_memory.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/image.h"

using namespace curvescan;

TEST_CASE("zeroed memory: blocks read zero, large or small, and again after reuse", "[paint][memory]") {
  for (const std::size_t n : {std::size_t{1}, std::size_t{1000}, kHugeBlockBytes / sizeof(float) + 1}) {
    std::vector<float, ZeroedAllocator<float>> block(n);
    CHECK(std::all_of(block.begin(), block.end(), [](float v) { return v == 0.0f; }));
    std::fill(block.begin(), block.end(), 1.0f);  // dirtied, then given back
  }
  const std::vector<float, ZeroedAllocator<float>> again(kHugeBlockBytes / sizeof(float) + 1);
  CHECK(std::all_of(again.begin(), again.end(), [](float v) { return v == 0.0f; }));
}

TEST_CASE("zeroed memory: a block's size is rounded up to huge pages only where it is mapped",
          "[paint][memory][limits]") {
  const std::size_t rounding = zeroed_block_rounding_bytes();
  CHECK(zeroed_block_bytes(100) == 100);  // calloc: no rounding
  CHECK(zeroed_block_bytes(kHugeBlockBytes - 1) == kHugeBlockBytes - 1);
  CHECK(zeroed_block_bytes(kHugeBlockBytes) == kHugeBlockBytes);  // whole huge pages already
  // 4,000,000 bytes: two huge pages (4,194,304 bytes) where blocks are mapped in them.
  CHECK(zeroed_block_bytes(4'000'000) == (rounding > 0 ? std::size_t{4} << 20 : 4'000'000));
}

TEST_CASE("the canvas counts its pixels as the memory they take against --max-memory",
          "[paint][memory][limits]") {
  // A 1000 x 1000 canvas: 4,000,000 bytes of pixels, in a block of zeroed_block_bytes() (4 MiB where
  // blocks are mapped in huge pages, which are resident once written).
  const auto taken = static_cast<std::int64_t>(zeroed_block_bytes(4'000'000));
  RenderLimits limits;
  limits.max_memory_bytes = taken;
  Result<Canvas> canvas = Canvas::create(1000, 1000, limits);
  REQUIRE(canvas);
  CHECK(canvas->memory_bytes() == taken);
  CHECK(canvas->image().at(999, 999) == Rgba8{});
  if (zeroed_block_rounding_bytes() == 0) return;  // no rounding here: nothing more to tell
  limits.max_memory_bytes = 4'000'000;             // the bare pixels fit, the huge pages they occupy do not
  const Result<Canvas> refused = Canvas::create(1000, 1000, limits);
  REQUIRE_FALSE(refused);
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message.find("--max-memory") != std::string::npos);
}
