// Difference regions (find_difference_regions and their use by compare_images) against a plain oracle:
// union-find over every pair of differing pixels whose Chebyshev distance is at most gap + 1, the
// definition in image_diff.h, with no dilation trick. Exact comparisons: both sides count integers.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <numeric>
#include <random>

#include "curvescan/diff/image_diff.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

struct Pixel {
  int x, y, delta;
};

std::vector<Pixel> differing_pixels(const std::vector<std::uint8_t>& deltas, int width) {
  std::vector<Pixel> pixels;
  for (std::size_t i = 0; i < deltas.size(); ++i) {
    if (deltas[i] != 0)
      pixels.push_back({static_cast<int>(i) % width, static_cast<int>(i) / width, deltas[i]});
  }
  return pixels;
}

/// The regions by definition: O(n²) pairs, union-find, statistics per root.
std::vector<DifferenceRegion> oracle_regions(const std::vector<std::uint8_t>& deltas, int width, int gap) {
  const std::vector<Pixel> pixels = differing_pixels(deltas, width);
  std::vector<std::size_t> parent(pixels.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    for (std::size_t j = i + 1; j < pixels.size(); ++j) {
      if (std::max(std::abs(pixels[i].x - pixels[j].x), std::abs(pixels[i].y - pixels[j].y)) <= gap + 1) {
        parent[find(i)] = find(j);
      }
    }
  }
  std::map<std::size_t, std::vector<Pixel>> members;
  for (std::size_t i = 0; i < pixels.size(); ++i) members[find(i)].push_back(pixels[i]);
  std::vector<DifferenceRegion> regions;
  for (const auto& [root, group] : members) {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    DifferenceRegion r;
    for (const Pixel& p : group) {
      x0 = std::min(x0, p.x);
      y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
      r.max_channel_delta = std::max(r.max_channel_delta, p.delta);
    }
    r.pixels = group.size();
    r.box = {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
    regions.push_back(r);
  }
  return regions;
}

/// A total order, to compare lists as multisets.
bool total_order(const DifferenceRegion& a, const DifferenceRegion& b) {
  return std::tie(a.box.y, a.box.x, a.box.width, a.box.height, a.pixels, a.max_channel_delta) <
         std::tie(b.box.y, b.box.x, b.box.width, b.box.height, b.pixels, b.max_channel_delta);
}

std::vector<DifferenceRegion> sorted(std::vector<DifferenceRegion> regions) {
  std::sort(regions.begin(), regions.end(), total_order);
  return regions;
}

std::vector<std::uint8_t> mask_of(int width, int height, std::initializer_list<std::pair<int, int>> pixels) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(width * height), 0);
  for (auto [x, y] : pixels) mask[static_cast<std::size_t>(y * width + x)] = 9;
  return mask;
}

std::uint64_t count_regions(const std::vector<std::uint8_t>& mask, int width, int height, int gap) {
  std::uint64_t count = 0;
  (void)find_difference_regions(mask, width, height, gap, 100, count);
  return count;
}

}  // namespace

TEST_CASE("regions: two pixels join exactly when at most `gap` pixels separate them", "[diff][regions]") {
  for (int gap : {0, 1, 3, 6}) {
    INFO("gap " << gap);
    const int w = 20, h = 20, linked = gap + 1, apart = gap + 2;
    // Along a row, a column and a diagonal; the second pixel near the right and bottom edges, where the
    // grown squares are clipped.
    CHECK(count_regions(mask_of(w, h, {{w - 1 - linked, 3}, {w - 1, 3}}), w, h, gap) == 1);
    CHECK(count_regions(mask_of(w, h, {{w - 1 - apart, 3}, {w - 1, 3}}), w, h, gap) == 2);
    CHECK(count_regions(mask_of(w, h, {{4, h - 1 - linked}, {4, h - 1}}), w, h, gap) == 1);
    CHECK(count_regions(mask_of(w, h, {{4, h - 1 - apart}, {4, h - 1}}), w, h, gap) == 2);
    CHECK(count_regions(mask_of(w, h, {{w - 1 - linked, h - 1 - linked}, {w - 1, h - 1}}), w, h, gap) == 1);
    CHECK(count_regions(mask_of(w, h, {{w - 1 - apart, h - 1 - linked}, {w - 1, h - 1}}), w, h, gap) == 2);
    // The anti-diagonal (up and to the right), which the top-left anchored squares meet at a corner.
    CHECK(count_regions(mask_of(w, h, {{2, 2 + linked}, {2 + linked, 2}}), w, h, gap) == 1);
    CHECK(count_regions(mask_of(w, h, {{2, 2 + apart}, {2 + apart, 2}}), w, h, gap) == 2);
  }
}

TEST_CASE("regions: box, pixel count and largest delta of each region, most pixels first",
          "[diff][regions]") {
  std::vector<std::uint8_t> mask(30 * 10, 0);
  const auto set = [&](int x, int y, std::uint8_t delta) {
    mask[static_cast<std::size_t>(y * 30 + x)] = delta;
  };
  set(2, 2, 10);  // region of 3 pixels, gap 1 links (2,2)-(4,2)-(4,4)
  set(4, 2, 200);
  set(4, 4, 30);
  set(20, 7, 5);  // lone pixel
  std::uint64_t count = 0;
  const std::vector<DifferenceRegion> regions = find_difference_regions(mask, 30, 10, 1, 10, count);
  CHECK(count == 2);
  REQUIRE(regions.size() == 2);
  CHECK(regions[0] == DifferenceRegion{{2, 2, 3, 3}, 3, 200});
  CHECK(regions[1] == DifferenceRegion{{20, 7, 1, 1}, 1, 5});
  // max_regions keeps the largest; the count still counts all.
  const std::vector<DifferenceRegion> one = find_difference_regions(mask, 30, 10, 1, 1, count);
  CHECK(count == 2);
  REQUIRE(one.size() == 1);
  CHECK(one[0].pixels == 3);
  CHECK(find_difference_regions(mask, 30, 10, 1, 0, count).empty());
  CHECK(count == 2);
  // A mask of the wrong size is refused, not read out of bounds.
  CHECK(find_difference_regions(mask, 31, 10, 1, 10, count).empty());
  CHECK(count == 0);
}

TEST_CASE("regions: random masks agree with the union-find oracle", "[diff][regions]") {
  std::mt19937 random(20261126);
  for (int trial = 0; trial < 60; ++trial) {
    const int width = 1 + static_cast<int>(random() % 48), height = 1 + static_cast<int>(random() % 36);
    const double density = std::array{0.01, 0.05, 0.2, 0.6}[trial % 4];
    const int gap = std::array{0, 1, 2, 3, 7}[trial % 5];
    std::bernoulli_distribution differs(density);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(width * height), 0);
    for (std::uint8_t& d : mask) {
      if (differs(random)) d = static_cast<std::uint8_t>(1 + random() % 255);
    }
    INFO("trial " << trial << ": " << width << " x " << height << ", density " << density << ", gap " << gap);
    const std::vector<DifferenceRegion> expected = oracle_regions(mask, width, gap);
    std::uint64_t count = 0;
    const std::vector<DifferenceRegion> all = find_difference_regions(mask, width, height, gap, 10000, count);
    CHECK(count == expected.size());
    CHECK(sorted(all) == sorted(expected));
    // Listing order: pixels descending, then top to bottom, then left to right.
    CHECK(std::is_sorted(all.begin(), all.end(), [](const DifferenceRegion& a, const DifferenceRegion& b) {
      return std::tie(b.pixels, a.box.y, a.box.x) < std::tie(a.pixels, b.box.y, b.box.x);
    }));
    // The largest three: the same pixel counts as the oracle's largest three.
    const std::vector<DifferenceRegion> top = find_difference_regions(mask, width, height, gap, 3, count);
    std::vector<std::uint64_t> expected_sizes;
    for (const DifferenceRegion& r : expected) expected_sizes.push_back(r.pixels);
    std::sort(expected_sizes.rbegin(), expected_sizes.rend());
    expected_sizes.resize(std::min<std::size_t>(3, expected_sizes.size()));
    std::vector<std::uint64_t> top_sizes;
    for (const DifferenceRegion& r : top) top_sizes.push_back(r.pixels);
    CHECK(top_sizes == expected_sizes);
  }
}

TEST_CASE("regions: compare_images lists them with their channel deltas", "[diff][regions]") {
  const Image expected = filled(40, 30, Rgba8{0, 160, 0, 255});
  Image actual = expected;
  paint(actual, 24, 8, 32, 16, Rgba8{0, 0, 200, 255});   // 64 pixels, largest delta 200 (blue)
  paint(actual, 2, 25, 4, 27, Rgba8{0, 100, 0, 255});    // 4 pixels, largest delta 60 (green)
  paint(actual, 12, 0, 13, 1, Rgba8{200, 160, 0, 255});  // a lone pixel, delta 200 (red)
  DiffOptions options;
  Result<ImageComparison> compared = compare_images(expected, actual, options);
  REQUIRE(compared.is_ok());
  CHECK(compared->metrics.region_count == 3);
  REQUIRE(compared->regions.size() == 3);
  CHECK(compared->regions[0] == DifferenceRegion{{24, 8, 8, 8}, 64, 200});
  CHECK(compared->regions[1] == DifferenceRegion{{2, 25, 2, 2}, 4, 60});
  CHECK(compared->regions[2] == DifferenceRegion{{12, 0, 1, 1}, 1, 200});

  // A gap wide enough joins the block and the lone pixel (dx 12, dy 8 to the block's corner: Chebyshev
  // distance 12, so 11 pixels between them).
  options.region_gap = 11;
  compared = compare_images(expected, actual, options);
  REQUIRE(compared.is_ok());
  CHECK(compared->metrics.region_count == 2);
  CHECK(compared->regions[0] == DifferenceRegion{{12, 0, 20, 16}, 65, 200});

  // Ignored and anti-aliasing pixels are not differing pixels: no region.
  options.ignore_regions = {{0, 0, 40, 30}};
  compared = compare_images(expected, actual, options);
  REQUIRE(compared.is_ok());
  CHECK(compared->metrics.region_count == 0);
  CHECK(compared->regions.empty());

  // Out-of-range options are refused by name.
  DiffOptions bad;
  bad.region_gap = 65;
  CHECK_THAT(validate_diff_options(bad).error().message, Catch::Contains("region gap"));
  bad = {};
  bad.max_regions = 10001;
  CHECK_THAT(validate_diff_options(bad).error().message, Catch::Contains("regions"));
}

TEST_CASE("regions: an image where every pixel differs is one region, in linear time", "[diff][regions]") {
  // 1500 x 1500 = 2.25 M pixels at the largest gap: the dilation costs the same whatever the gap, where
  // testing the (2g + 3)² neighbours of each pixel would cost 17,161 tests a pixel.
  const Image expected = filled(1500, 1500, Rgba8{255, 255, 255, 255});
  const Image actual = filled(1500, 1500, Rgba8{0, 0, 0, 255});
  DiffOptions options;
  options.region_gap = 64;
  options.make_diff_image = false;
  const Result<ImageComparison> compared = compare_images(expected, actual, options);
  REQUIRE(compared.is_ok());
  CHECK(compared->metrics.region_count == 1);
  REQUIRE(compared->regions.size() == 1);
  CHECK(compared->regions[0] == DifferenceRegion{{0, 0, 1500, 1500}, 2'250'000, 255});
}
