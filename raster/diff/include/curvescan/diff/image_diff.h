// Image comparison for regression tests and for `curvescan diff`: metrics, per-pixel thresholds,
// anti-aliasing detection, ignore regions, a diff image, an HTML report and the golden-test helper.
//
// Conventions (docs/diff.md has the user-facing version):
// - "expected" (A) is the reference, "actual" (B) the image under test; the diff image is drawn over A.
// - Every fully transparent pixel is the same pixel, (0, 0, 0, 0), whatever its colour bits: a pixel with
//   a = 0 has no colour (image.h's premultiplied convention), and PNG files often keep junk there.
// - The statistics (max |Δ|, mean |Δ|, RMSE, PSNR) are over the four premultiplied channels R, G, B, A of
//   every compared pixel (pixels inside an ignore region are not compared), in levels 0..255.
// - Whether one pixel "differs" is decided by the per-pixel metric: pixelmatch's perceptual YIQ distance
//   (Kotsarenko and Ramos, "Measuring perceived color difference using YIQ NTSC transmission color space in
//   mobile applications", 2010, as pixelmatch uses it) on colours blended over white, or a plain largest
//   per-channel |Δ|. A differing pixel can be classed as anti-aliasing (pixelmatch's detector, after
//   Vysniauskas, "Anti-aliased pixel and intensity slope detector", 2009) and then ignored.
// - The images are "the same" when the count of differing, not ignored pixels is within the per-image
//   tolerance (max_different_pixels and/or max_different_percent).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan {

/// How one pixel of A is judged against the same pixel of B.
enum class PixelMetric {
  kPerceptual,  ///< pixelmatch's YIQ distance of the colours blended over white, against yiq_threshold
  kPerChannel,  ///< the largest |Δ| of the premultiplied R, G, B, A bytes, against channel_tolerance
};

/// A rectangle of pixels, x and y of its top-left pixel, in image pixels; width or height 0 = empty.
struct PixelBox {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const PixelBox&) const = default;
  [[nodiscard]] bool empty() const noexcept { return width <= 0 || height <= 0; }
};

/// What to compare and how strictly. validate_diff_options() states the valid ranges.
struct DiffOptions {
  PixelMetric metric = PixelMetric::kPerceptual;
  /// kPerceptual: pixelmatch's threshold in [0, 1] (its default 0.1). A pixel differs when its squared YIQ
  /// distance exceeds 35215·t², 35215 being the largest squared distance (black against white).
  double yiq_threshold = 0.1;
  /// kPerChannel: a pixel differs when some premultiplied channel differs by more than this, in [0, 255].
  int channel_tolerance = 0;
  /// Differing pixels that look like anti-aliasing in either image (see the file comment) are counted
  /// apart (DiffMetrics::antialiased_pixels), drawn yellow, and do not make the images different.
  bool ignore_antialiasing = false;
  /// Pixels inside any of these rectangles are not compared at all (parts of them outside the image are
  /// clipped away).
  std::vector<PixelBox> ignore_regions;
  /// Per-image tolerance. The images are the same when the differing pixels are at most this many AND at
  /// most this percentage of all width·height pixels; a limit left unset does not constrain, and with both
  /// unset no differing pixel is tolerated.
  std::optional<std::uint64_t> max_different_pixels;
  std::optional<double> max_different_percent;
  /// Whether compare_images() draws ImageComparison::diff_image.
  bool make_diff_image = true;
  /// Difference regions (see DifferenceRegion): two differing pixels belong to the same region when at
  /// most `region_gap` pixels separate them, that is when their Chebyshev distance is at most
  /// region_gap + 1 (0 = 8-connected clusters only), directly or through a chain of such pixels. In [0, 64].
  int region_gap = 3;
  /// The regions listed in ImageComparison::regions: the largest this many (DiffMetrics::region_count
  /// counts them all). In [0, 10000].
  std::size_t max_regions = 50;
};

/// Fails with kInvalidArgument, naming the option, when a value is out of range or NaN: yiq_threshold
/// outside [0, 1], channel_tolerance outside [0, 255], max_different_percent outside [0, 100], an ignore
/// region with a negative width or height, region_gap outside [0, 64], max_regions above 10000.
[[nodiscard]] Status validate_diff_options(const DiffOptions& options);

/// The measurements of one comparison. For a size mismatch only the four sizes are set.
struct DiffMetrics {
  int expected_width = 0, expected_height = 0;
  int actual_width = 0, actual_height = 0;
  std::uint64_t total_pixels = 0;        ///< width·height
  std::uint64_t compared_pixels = 0;     ///< total_pixels less the pixels inside ignore regions
  std::uint64_t changed_pixels = 0;      ///< compared pixels whose bytes differ at all
  std::uint64_t different_pixels = 0;    ///< compared pixels that differ by the per-pixel metric, not AA
  std::uint64_t antialiased_pixels = 0;  ///< differing pixels classed as anti-aliasing (only when ignored)
  double different_percent = 0.0;        ///< 100·different_pixels / total_pixels
  int max_channel_delta = 0;             ///< largest |Δ| of one premultiplied channel, levels 0..255
  double mean_channel_delta = 0.0;       ///< mean |Δ| over the 4 channels of the compared pixels
  double rmse = 0.0;                     ///< sqrt(mean Δ²) over the same samples, levels
  /// 20·log10(255 / rmse) in dB; +infinity when rmse is 0 (identical compared pixels).
  double psnr = 0.0;
  /// The smallest box holding every differing pixel (not the AA or ignored ones); empty when none.
  PixelBox difference_bounds;
  /// How many difference regions the differing pixels form (DiffOptions::region_gap), all of them, also
  /// those beyond DiffOptions::max_regions.
  std::uint64_t region_count = 0;
};

/// One cluster of differing pixels (DiffOptions::region_gap says which pixels cluster): what a reviewer
/// looks at first, drawn as a box in the HTML report and listed in the JSON output.
struct DifferenceRegion {
  PixelBox box;                ///< the smallest box holding the region's differing pixels
  std::uint64_t pixels = 0;    ///< differing pixels in the region
  int max_channel_delta = 0;   ///< largest |Δ| of one premultiplied channel among them, levels 0..255
  bool operator==(const DifferenceRegion&) const = default;
};

enum class DiffVerdict {
  kSame,          ///< within the per-image tolerance
  kDifferent,     ///< more differing pixels than the tolerance allows
  kSizeMismatch,  ///< the images have different sizes; nothing else was compared
};

struct ImageComparison {
  DiffVerdict verdict = DiffVerdict::kSame;
  DiffMetrics metrics;
  /// When DiffOptions::make_diff_image and the sizes match: an opaque image of A's size showing A as a
  /// faded greyscale copy (pixelmatch's drawing, alpha 0.1, over white), differing pixels red
  /// (255, 0, 0), anti-aliasing pixels yellow (255, 255, 0) and ignore regions tinted blue.
  Image diff_image;
  /// The largest DiffOptions::max_regions difference regions, by pixel count, most pixels first (ties:
  /// top to bottom, then left to right); empty for a size mismatch or when no pixel differs.
  std::vector<DifferenceRegion> regions;
};

/// The difference regions of a per-pixel map: `deltas` holds width·height bytes, row by row, 0 for a pixel
/// that does not differ and its largest channel |Δ| (1..255) for one that does. Returns the largest
/// `max_regions` regions in the order of ImageComparison::regions and sets `region_count` to the number
/// of all regions. Linear time; the extra memory is one byte per pixel plus the search frontier.
[[nodiscard]] std::vector<DifferenceRegion> find_difference_regions(const std::vector<std::uint8_t>& deltas,
                                                                    int width, int height, int region_gap,
                                                                    std::size_t max_regions,
                                                                    std::uint64_t& region_count);

/// Compares `expected` (A) with `actual` (B). Fails only when validate_diff_options() fails.
[[nodiscard]] Result<ImageComparison> compare_images(const Image& expected, const Image& actual,
                                                     const DiffOptions& options);

/// Pixelmatch's signed perceptual distance between two premultiplied pixels (exposed for the tests): the
/// squared YIQ distance of both colours blended over white, negative when `a` is the brighter one, 0 when
/// the canonical pixels are equal. Its magnitude is at most 35215 (black against white).
[[nodiscard]] double perceptual_delta(Rgba8 a, Rgba8 b) noexcept;

/// True when pixel (x, y) of `image` looks like anti-aliasing in the sense of pixelmatch: at most two of
/// its neighbours equal it, it has both a darker and a brighter neighbour, and the darkest or the
/// brightest of those has three or more equal neighbours in `image` and in `other` alike. Both images
/// must have the same size and (x, y) must lie inside.
[[nodiscard]] bool is_antialiased_pixel(const Image& image, const Image& other, int x, int y) noexcept;

// ---- reports --------------------------------------------------------------------------------------

/// Where one compared file ended up in a report.
enum class DiffOutcome {
  kPassed,   ///< same within tolerance
  kFailed,   ///< different, or sizes differ
  kNew,      ///< an actual image without an expected one
  kMissing,  ///< an expected image without an actual one
  kError,    ///< a file could not be read (corrupt, unreadable); listed with the failures
};

/// "passed", "failed", "new", "missing", "error".
[[nodiscard]] std::string_view to_string(DiffOutcome outcome) noexcept;

/// One line of a report. The image references are URLs relative to the report's HTML file (the report
/// copies images beside itself; an empty reference shows no image).
struct DiffReportEntry {
  std::string name;  ///< the relative path that paired the two files, e.g. "shapes/circle.png"
  DiffOutcome outcome = DiffOutcome::kPassed;
  std::string message;                        ///< one sentence: why it failed, or the read error
  std::optional<ImageComparison> comparison;  ///< metrics and verdict when both images were read
  std::string expected_image, actual_image, diff_image;
};

/// The status an entry is filed under in the report: to_string(outcome), except "size-mismatch" for a
/// failed entry whose images differ in size.
[[nodiscard]] std::string_view report_status(const DiffReportEntry& entry) noexcept;

/// Writes a self-contained HTML report (inline CSS and JS, no external resource, works from file://; the
/// images are the relative references of the entries). The cases are listed failures first (error,
/// failed, size-mismatch, new, missing, passed), with a count and a show/hide filter per status. A case
/// with both images offers three views: side by side (expected, actual, diff), a slider that reveals the
/// actual image over the expected one, and blink (the two in turn, at an interval or on a key); its
/// difference regions are boxed on every image. Keyboard shortcuts are listed on the page. The view,
/// zoom, slider position, blink state, filter and current case can be set in the URL fragment, e.g.
/// index.html#view=slider&pos=30&zoom=4&blink=off&frame=actual&regions=off&filter=failed,new&case=0.
/// The page's script marks <body data-report-ready="1"> once it ran without error and every image has
/// loaded or failed, with data-images-loaded / data-images-broken counts, so that a headless browser test
/// can check it. Written atomically (a temporary file and a rename).
[[nodiscard]] Status write_html_report(const std::filesystem::path& html_file, std::string_view title,
                                       const std::vector<DiffReportEntry>& entries,
                                       const DiffOptions& options);

/// Percent-encodes a relative path for use as a URL in the report (keeps letters, digits, "-._~/").
[[nodiscard]] std::string relative_url(const std::filesystem::path& relative_path);
/// `text` escaped for HTML and XML attribute values and text (& < > " ' as character references); the
/// control characters XML 1.0 forbids even escaped become '?', so one function serves the HTML report
/// and the JUnit XML alike.
[[nodiscard]] std::string markup_escape(std::string_view text);

/// Writes `text` to `path` through write_output_file (file_io.h), creating the parent directories.
[[nodiscard]] Status write_text_file_atomically(const std::filesystem::path& path, std::string_view text);

// ---- the report directory: pruning what earlier reports left ----------------------------------------

/// The file, inside a report directory, that lists what the report wrote there.
inline constexpr const char* kReportManifestName = ".curvescan-report-files";

/// What update_report_manifest() did with the files of the previous report.
struct ReportPruning {
  std::size_t removed_files = 0;        ///< stale files removed
  std::size_t removed_directories = 0;  ///< directories left empty by them, removed
  /// Stale files kept because they changed since the report wrote them (or are no longer regular files):
  /// someone else's now. Paths relative to the report directory.
  std::vector<std::string> kept_changed;
};

/// Call after a report wrote all its files into `report_dir`. `written` holds their paths relative to
/// `report_dir` (generic form, e.g. "images/a.png/diff.png"). First removes every file the previous
/// manifest (kReportManifestName) lists that `written` does not, but only when it is still a regular file
/// inside `report_dir` with the size and content hash the manifest recorded: a file the report did not
/// write, or one changed since, is never removed. Then removes the directories those removals left empty,
/// up to but not including `report_dir`. Last writes the new manifest: one line per written file with its
/// size and a 64-bit FNV-1a hash of its bytes. A missing, unreadable or malformed manifest removes nothing.
[[nodiscard]] Result<ReportPruning> update_report_manifest(const std::filesystem::path& report_dir,
                                                           const std::vector<std::string>& written);

// ---- golden tests ---------------------------------------------------------------------------------

/// Compares `actual` with the PNG at `golden`. Succeeds when they are the same within `options`. On any
/// failure (golden missing or unreadable, size mismatch, difference) writes into
/// report_dir/<golden file stem>/ the files actual.png, and when the golden was read also expected.png and
/// diff.png, plus index.html (write_html_report), and fails with a message that states the metrics and
/// the path of that index.html. A missing golden is reported as kIoError with the advice to review
/// actual.png and copy it to `golden`.
[[nodiscard]] Status compare_to_golden(const Image& actual, const std::filesystem::path& golden,
                                       const DiffOptions& options, const std::filesystem::path& report_dir);

/// One sentence with the key metrics of a comparison, e.g. "412 of 65536 pixels differ (0.629%), max
/// channel delta 255, RMSE 12.3, PSNR 26.3 dB, in the box x=10 y=4 w=30 h=12".
[[nodiscard]] std::string describe_comparison(const ImageComparison& comparison);

}  // namespace curvescan
