// The comparison as the CLI and the golden tests see it: images read from PNG files of every layout
// (written here with libpng directly), corrupt files, and compare_to_golden's failure evidence.
#include <catch2/catch.hpp>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

/// A small image with opaque, translucent and transparent pixels of several colours.
Image sample_image() {
  Image image = filled(6, 4, Rgba8{0, 0, 0, 0});
  paint(image, 0, 0, 3, 2, Rgba8{255, 0, 0, 255});
  paint(image, 3, 0, 6, 2, Rgba8{0, 64, 128, 128});  // straight (0, 127.5→128, 255) at 50%
  paint(image, 0, 2, 6, 3, Rgba8{30, 60, 90, 255});
  return image;
}

ImageComparison compare_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  const Result<Image> image_a = read_png(a);
  const Result<Image> image_b = read_png(b);
  REQUIRE(image_a.is_ok());
  REQUIRE(image_b.is_ok());
  DiffOptions exact;
  exact.metric = PixelMetric::kPerChannel;
  Result<ImageComparison> c = compare_images(*image_a, *image_b, exact);
  REQUIRE(c.is_ok());
  return std::move(*c);
}

}  // namespace

TEST_CASE("a 16-bit PNG and a palette PNG compare equal to the 8-bit PNG of the same pixels", "[diff][png]") {
  ScratchDirectory dir("png-layouts");
  const Image image = sample_image();
  const auto rows8 = straight_rows(image);
  REQUIRE(write_raw_png(dir / "rgba8.png", image.width(), image.height(), 8, PNG_COLOR_TYPE_RGBA, rows8));

  // 16-bit: v·257 is exactly v on the 16-bit scale, which the reader scales back to v (png_set_scale_16).
  std::vector<std::vector<unsigned char>> rows16;
  for (const auto& row : rows8) {
    std::vector<unsigned char> wide;
    for (unsigned char v : row) wide.insert(wide.end(), {v, v});  // big-endian v·257 = (v << 8) | v
    rows16.push_back(std::move(wide));
  }
  REQUIRE(write_raw_png(dir / "rgba16.png", image.width(), image.height(), 16, PNG_COLOR_TYPE_RGBA, rows16));

  // Palette: one entry per distinct straight colour, alpha through tRNS.
  std::vector<png_color> palette;
  std::vector<unsigned char> alphas;
  std::vector<std::vector<unsigned char>> indexed;
  for (const auto& row : rows8) {
    std::vector<unsigned char> out;
    for (std::size_t i = 0; i < row.size(); i += 4) {
      std::size_t k = 0;
      while (k < palette.size() && !(palette[k].red == row[i] && palette[k].green == row[i + 1] &&
                                     palette[k].blue == row[i + 2] && alphas[k] == row[i + 3])) {
        ++k;
      }
      if (k == palette.size()) {
        palette.push_back({row[i], row[i + 1], row[i + 2]});
        alphas.push_back(row[i + 3]);
      }
      out.push_back(static_cast<unsigned char>(k));
    }
    indexed.push_back(std::move(out));
  }
  REQUIRE(write_raw_png(dir / "palette.png", image.width(), image.height(), 8, PNG_COLOR_TYPE_PALETTE,
                        indexed, palette, alphas));

  CHECK(compare_files(dir / "rgba8.png", dir / "rgba16.png").metrics.changed_pixels == 0);
  CHECK(compare_files(dir / "rgba8.png", dir / "palette.png").metrics.changed_pixels == 0);
}

TEST_CASE("transparent pixels with different colour bits in the files compare equal", "[diff][png]") {
  ScratchDirectory dir("png-junk");
  const Image image = sample_image();
  REQUIRE(write_raw_png(dir / "zero.png", 6, 4, 8, PNG_COLOR_TYPE_RGBA, straight_rows(image, 0)));
  REQUIRE(write_raw_png(dir / "junk.png", 6, 4, 8, PNG_COLOR_TYPE_RGBA, straight_rows(image, 201)));
  const ImageComparison c = compare_files(dir / "zero.png", dir / "junk.png");
  CHECK(c.verdict == DiffVerdict::kSame);
  CHECK(c.metrics.changed_pixels == 0);
}

TEST_CASE("a corrupt or truncated PNG is a read error, never a comparison", "[diff][png]") {
  ScratchDirectory dir("png-corrupt");
  REQUIRE(write_png(sample_image(), dir / "good.png").is_ok());
  const std::string bytes = read_text(dir / "good.png");
  std::ofstream(dir / "truncated.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::ofstream(dir / "garbage.png", std::ios::binary) << "this is not a PNG file at all";
  CHECK_FALSE(read_png(dir / "truncated.png").is_ok());
  CHECK_FALSE(read_png(dir / "garbage.png").is_ok());
}

TEST_CASE("compare_to_golden passes silently and on failure leaves the evidence and names the report",
          "[diff][golden]") {
  ScratchDirectory dir("golden");
  const Image golden = sample_image();
  REQUIRE(write_png(golden, dir / "shape.png").is_ok());
  const std::filesystem::path reports = dir / "reports";

  CHECK(compare_to_golden(golden, dir / "shape.png", {}, reports).is_ok());
  CHECK_FALSE(std::filesystem::exists(reports));  // nothing written on success

  Image changed = golden;
  paint(changed, 1, 3, 3, 4, Rgba8{0, 0, 255, 255});
  const Status failed = compare_to_golden(changed, dir / "shape.png", {}, reports);
  REQUIRE_FALSE(failed.is_ok());
  const std::filesystem::path report = reports / "shape" / "index.html";
  CHECK_THAT(failed.error().message, Catch::Contains(report.string()));
  CHECK_THAT(failed.error().message, Catch::Contains("2 of 24 pixels differ"));
  for (const char* file : {"index.html", "actual.png", "expected.png", "diff.png"}) {
    CHECK(std::filesystem::exists(reports / "shape" / file));
  }
  const Result<Image> written_actual = read_png(reports / "shape" / "actual.png");
  REQUIRE(written_actual.is_ok());
  CHECK(*written_actual == changed);

  const Status missing = compare_to_golden(changed, dir / "absent.png", {}, reports);
  REQUIRE_FALSE(missing.is_ok());
  CHECK_THAT(missing.error().message, Catch::Contains("does not exist"));
  CHECK(std::filesystem::exists(reports / "absent" / "actual.png"));
}
