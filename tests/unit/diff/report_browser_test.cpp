// The HTML report in headless Chromium: it loads from file:// with the network cut off, its script runs,
// and what it shows is checked on the pixels of screenshots — the region boxes around the differing
// region on each image, the slider revealing the actual image over the expected one up to its handle, the
// blink view showing one image at a time — and, through a page that drives the report in a frame, its
// keyboard shortcuts, blink timer, filter and slider drag.
//
// Screenshot metrics: the test images are flat colours scaled 4x with image-rendering: pixelated, so the
// sizes and positions of colour clusters are exact integers up to Chromium's snapping of a fractional
// layout position to device pixels, hence the tolerance of 1 pixel on positions and sizes. Colours are
// matched within 6 levels: the PNGs are untagged sRGB and Chromium draws them unchanged here (0 levels
// measured), the margin covers a build that converts through a colour profile.
#include <catch2/catch.hpp>
#include <cstring>
#include <nlohmann/json.hpp>

#include "browser_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

namespace fs = std::filesystem;

constexpr Rgba8 kGreen{0, 160, 0, 255};
constexpr Rgba8 kBlue{0, 0, 200, 255};
constexpr Rgba8 kRed{255, 0, 0, 255};
constexpr Rgba8 kMagenta{255, 0, 255, 255};  // the region boxes (--box in report_page_assets.h)
constexpr int kColourTolerance = 6;          // see the file comment
constexpr int kZoom = 4;

/// A report of one failed case (a green 40 x 30 image, the actual one with a blue 8 x 8 block at
/// (24, 8)), one new and one passed file; `actual` replaces the actual image when given.
fs::path write_report(const ScratchDirectory& dir, const Image& expected, const Image& actual) {
  fs::create_directories(dir / "images dir");
  REQUIRE(write_png(expected, dir / "images dir/expected.png").is_ok());
  REQUIRE(write_png(actual, dir / "images dir/actual.png").is_ok());
  Result<ImageComparison> comparison = compare_images(expected, actual, {});
  REQUIRE(comparison.is_ok());
  REQUIRE(write_png(comparison->diff_image, dir / "images dir/diff.png").is_ok());

  DiffReportEntry passed;
  passed.name = "passed.png";
  DiffReportEntry failed;
  failed.name = "scenes/<quoted & odd> name.png";  // escaped in the page
  failed.outcome = DiffOutcome::kFailed;
  failed.message = describe_comparison(*comparison);
  failed.comparison = std::move(*comparison);
  failed.comparison->diff_image = Image();
  failed.expected_image = relative_url("images dir/expected.png");
  failed.actual_image = relative_url("images dir/actual.png");
  failed.diff_image = relative_url("images dir/diff.png");
  DiffReportEntry added;
  added.name = "new.png";
  added.outcome = DiffOutcome::kNew;
  added.actual_image = relative_url("images dir/actual.png");
  // Given passed first: the page lists the failure first all the same.
  REQUIRE(write_html_report(dir / "report.html", "browser test", {passed, failed, added}, {}).is_ok());
  return dir / "report.html";
}

Image green_image() {
  return filled(40, 30, kGreen);
}

Image actual_with_block() {
  Image actual = green_image();
  paint(actual, 24, 8, 32, 16, kBlue);
  return actual;
}

/// Within one pixel: the layout snapping of the file comment.
bool about(int value, int expected) {
  return std::abs(value - expected) <= 1;
}

}  // namespace

TEST_CASE("report in Chromium: loads offline from file://, script runs, failures first",
          "[diff][report][browser]") {
  INFO("install Chromium (Debian package 'chromium'): the report tests need " << kChromium);
  REQUIRE(fs::exists(kChromium));

  ScratchDirectory dir("report-browser");
  const fs::path html = write_report(dir, green_image(), actual_with_block());
  const std::string page = read_text(html);
  // Nothing outside the page but its own images: no scheme, no protocol-relative URL, no font.
  CHECK_THAT(page, !Catch::Contains("http:") && !Catch::Contains("https:") && !Catch::Contains("//cdn"));
  CHECK_THAT(page,
             !Catch::Contains("<link") && !Catch::Contains("@font-face") && !Catch::Contains("<script src"));
  CHECK_THAT(page, !Catch::Contains("src=\"//") && !Catch::Contains("url("));

  // A hand-edited link with a malformed escape: that pair is ignored, the rest (zoom 2) applies.
  const std::string dom = dump_dom(file_url(html, "view=%E0%A4%A&zoom=2"), dir);
  INFO("DOM: " << dom.substr(0, 3000));
  CHECK(body_attribute(dom, "data-report-ready") == "1");
  CHECK(body_attribute(dom, "data-script-error") == "<absent>");
  // Failed case: side by side 3, slider 2, blink 2; the new case 1.
  CHECK(body_attribute(dom, "data-images-loaded") == "8");
  CHECK(body_attribute(dom, "data-images-broken") == "0");
  CHECK(body_attribute(dom, "data-shown-cases") == "3");
  CHECK_THAT(dom, Catch::Contains("&lt;quoted &amp; odd&gt; name.png"));
  CHECK_THAT(dom, Catch::Contains("style=\"width: 80px; height: 60px;\""));  // the 40 x 30 images at 2x
  // Failures first, whatever the order given.
  const std::size_t failed_at = dom.find("data-status=\"failed\" tabindex");
  const std::size_t new_at = dom.find("data-status=\"new\" tabindex");
  const std::size_t passed_at = dom.find("data-status=\"passed\" tabindex");
  CHECK(failed_at < new_at);
  CHECK(new_at < passed_at);
  CHECK(passed_at != std::string::npos);
}

TEST_CASE("report screenshot: the region box surrounds the differing block on every image",
          "[diff][report][browser][screenshot]") {
  REQUIRE(fs::exists(kChromium));
  ScratchDirectory dir("report-shot-regions");
  const fs::path html = write_report(dir, green_image(), actual_with_block());
  const Image shot = screenshot(file_url(html, "zoom=4&blink=off&filter=failed"), dir, 1000, 1400);

  // The actual image's blue block and the diff image's red block, 8 x 8 pixels at zoom 4.
  const std::vector<PixelBox> blue = clusters(shot, near(kBlue, kColourTolerance));
  const std::vector<PixelBox> red = clusters(shot, near(kRed, kColourTolerance));
  REQUIRE(blue.size() == 1);
  REQUIRE(red.size() == 1);
  CHECK(about(blue[0].width, 8 * kZoom));
  CHECK(about(blue[0].height, 8 * kZoom));
  CHECK(about(red[0].width, 8 * kZoom));

  // One magenta ring per image (expected, actual, diff): the 32 x 32 box and its 2-pixel outline outside.
  std::vector<PixelBox> rings = clusters(shot, near(kMagenta, kColourTolerance));
  std::sort(rings.begin(), rings.end(), [](const PixelBox& a, const PixelBox& b) { return a.x < b.x; });
  REQUIRE(rings.size() == 3);
  for (const PixelBox& ring : rings) {
    CHECK(about(ring.width, 8 * kZoom + 4));
    CHECK(about(ring.height, 8 * kZoom + 4));
    CHECK(about(ring.y, blue[0].y - 2));
  }
  // The actual image's ring and the diff image's ring lie just outside their blocks.
  CHECK(about(rings[1].x, blue[0].x - 2));
  CHECK(about(rings[2].x, red[0].x - 2));
  // The expected image has no block: its ring sits at the block's position in the image, found from the
  // image's own top-left corner (the first green pixel of the leftmost frame).
  std::vector<PixelBox> green = clusters(shot, near(kGreen, kColourTolerance));
  std::sort(green.begin(), green.end(), [](const PixelBox& a, const PixelBox& b) { return a.x < b.x; });
  REQUIRE(green.size() >= 2);
  CHECK(about(green[0].width, 40 * kZoom));
  CHECK(about(green[0].height, 30 * kZoom));
  CHECK(about(rings[0].x, green[0].x + 24 * kZoom - 2));
  CHECK(about(rings[0].y, green[0].y + 8 * kZoom - 2));
  // Inside the ring of the expected image the image shows through, unmarked.
  CHECK(near(kGreen,
             kColourTolerance)(shot.at(rings[0].x + rings[0].width / 2, rings[0].y + rings[0].height / 2)));

  // regions=off hides every box.
  const Image plain =
      screenshot(file_url(html, "zoom=4&blink=off&filter=failed&regions=off"), dir, 1000, 1400);
  CHECK(count_pixels(plain, near(kMagenta, kColourTolerance)) == 0);
  CHECK(clusters(plain, near(kBlue, kColourTolerance)).size() == 1);
}

TEST_CASE("report screenshot: the slider shows the actual image left of the handle, the expected right",
          "[diff][report][browser][screenshot]") {
  REQUIRE(fs::exists(kChromium));
  ScratchDirectory dir("report-shot-slider");
  // Different everywhere: every column shows which image is on top.
  const fs::path html = write_report(dir, green_image(), filled(40, 30, kBlue));
  for (int pos : {25, 75}) {
    INFO("slider at " << pos << "%");
    const Image shot = screenshot(file_url(html, "view=slider&pos=" + std::to_string(pos) +
                                                     "&zoom=4&blink=off&regions=off&filter=failed"),
                                  dir, 1000, 1400);
    const std::vector<PixelBox> blue = clusters(shot, near(kBlue, kColourTolerance));
    const std::vector<PixelBox> green = clusters(shot, near(kGreen, kColourTolerance));
    REQUIRE(blue.size() == 1);
    REQUIRE(green.size() == 1);
    const int image_width = 40 * kZoom, split = image_width * pos / 100;
    // Both images show, side by side in one frame of the image's size: actual [0, split), the handle
    // line (2 pixels), expected after it.
    CHECK(about(blue[0].width, split));
    CHECK(about(blue[0].height, 30 * kZoom));
    CHECK(about(green[0].y, blue[0].y));
    CHECK(about(green[0].height, 30 * kZoom));
    CHECK(blue[0].x + blue[0].width <= green[0].x);
    CHECK(about(green[0].x + green[0].width - blue[0].x, image_width));
    CHECK(green[0].x - (blue[0].x + blue[0].width) <= 3);  // the handle line only
  }
}

TEST_CASE("report screenshot: blink shows one image at a time", "[diff][report][browser][screenshot]") {
  REQUIRE(fs::exists(kChromium));
  ScratchDirectory dir("report-shot-blink");
  const fs::path html = write_report(dir, green_image(), actual_with_block());
  const std::string state = "view=blink&zoom=4&blink=off&filter=failed&frame=";
  const Image actual = screenshot(file_url(html, state + "actual"), dir, 1000, 1400);
  const std::vector<PixelBox> blue = clusters(actual, near(kBlue, kColourTolerance));
  REQUIRE(blue.size() == 1);
  CHECK(about(blue[0].width, 8 * kZoom));
  CHECK(clusters(actual, near(kMagenta, kColourTolerance)).size() == 1);  // one image, one box
  const Image expected = screenshot(file_url(html, state + "expected"), dir, 1000, 1400);
  CHECK(count_pixels(expected, near(kBlue, kColourTolerance)) == 0);
  const std::vector<PixelBox> ring = clusters(expected, near(kMagenta, kColourTolerance));
  REQUIRE(ring.size() == 1);
  CHECK(about(ring[0].x, blue[0].x - 2));  // the same place in both frames
  CHECK(about(ring[0].y, blue[0].y - 2));
}

TEST_CASE("report in Chromium: keyboard shortcuts, blink timer, filter and slider drag",
          "[diff][report][browser][keyboard]") {
  REQUIRE(fs::exists(kChromium));
  ScratchDirectory dir("report-keys");
  const fs::path html = write_report(dir, green_image(), actual_with_block());
  // A page beside the report that opens it in a frame, presses keys in it and writes what changed. The
  // two file:// pages may script each other only with --allow-file-access-from-files.
  write_text(dir / "drive.html", R"html(<!DOCTYPE html><html><body>
<iframe id="report" src="report.html#interval=100" width="1000" height="800"></iframe><pre id="result">pending</pre>
<script>
var frame = document.getElementById('report');
frame.addEventListener('load', function () {
  var win = frame.contentWindow, doc = frame.contentDocument, out = {};
  function key(k) { doc.dispatchEvent(new win.KeyboardEvent('keydown', { key: k, bubbles: true })); }
  function pointer(type, el, fraction) {
    var r = el.getBoundingClientRect();
    el.dispatchEvent(new win.PointerEvent(type, { clientX: r.left + r.width * fraction, clientY: r.top + 2,
                                                   pointerId: 1, bubbles: true }));
  }
  function ready() {
    if (doc.body.getAttribute('data-report-ready') !== '1') { setTimeout(ready, 20); return; }
    var entry = doc.querySelector('article.case[data-views]');
    // The blink timer is timed over its first ten intervals: the test goes on at the eleventh flip, or
    // after 8 s with what it saw.
    var flips = 0, flipTimes = [], goneOn = false;
    function goOn() { if (!goneOn) { goneOn = true; afterBlinking(); } }
    new win.MutationObserver(function (records) {
      flips += records.length;
      if (flipTimes.length < 11) {
        flipTimes.push(performance.now());
        if (flipTimes.length === 11) setTimeout(goOn, 0);
      }
    }).observe(entry, { attributes: true, attributeFilter: ['data-frame'] });
    out.blinkingAtStart = doc.body.getAttribute('data-blinking');
    setTimeout(goOn, 8000);
    function afterBlinking() {
      out.blinkFlipsTimed = flipTimes.length;
      var gaps = [];
      for (var i = 1; i < flipTimes.length; ++i) gaps.push(flipTimes[i] - flipTimes[i - 1]);
      gaps.sort(function (a, b) { return a - b; });
      out.medianGapMs = gaps.length === 10 ? (gaps[4] + gaps[5]) / 2 : -1;
      key('b'); out.blinkingAfterB = doc.body.getAttribute('data-blinking');
      flips = 0;
      var before = entry.dataset.frame; key('t'); out.frameFlippedByT = entry.dataset.frame !== before;
      key('2'); out.viewAfter2 = entry.dataset.view;
      out.sliderShown = !entry.querySelector('.view[data-view=slider]').hidden;
      key('j'); out.currentAfterJ = Array.prototype.indexOf.call(doc.querySelectorAll('article.case'), doc.querySelector('article.current'));
      key('ArrowRight'); out.posAfterRight = entry.dataset.pos;
      key('3'); out.viewAfter3 = entry.dataset.view;
      key('1'); out.viewAfter1 = entry.dataset.view;
      key('r'); out.regionsHidden = doc.body.classList.contains('no-regions');
      key('r'); out.regionsShownAgain = !doc.body.classList.contains('no-regions');
      var img = entry.querySelector('.view[data-view=side] img');
      var w1 = img.getBoundingClientRect().width; key('+'); var w2 = img.getBoundingClientRect().width;
      out.zoomRatio = w2 / w1; out.zoomSelect = doc.getElementById('zoom').value;
      var passed = doc.querySelector('.filters input[data-status=passed]');
      passed.click();
      out.shownAfterFilter = doc.body.getAttribute('data-shown-cases');
      out.passedHidden = doc.querySelector('article.case[data-status=passed]').hidden;
      key('2');
      var slider = entry.querySelector('.frame.slider');
      pointer('pointerdown', slider, 0.2); out.posAtDown = entry.dataset.pos;
      pointer('pointermove', slider, 0.8); out.posAfterDrag = entry.dataset.pos;
      pointer('pointerup', slider, 0.8); pointer('pointermove', slider, 0.1); out.posAfterRelease = entry.dataset.pos;
      out.clip = entry.querySelector('.slider img.over').style.clipPath;
      out.hash = win.location.hash;
      out.intervalShown = doc.getElementById('interval').value;  // 100 ms is not in the list: added
      setTimeout(function () {  // the observer reports between tasks; half a second paused
        out.flipsWhilePaused = flips;
        out.scriptError = doc.body.getAttribute('data-script-error');
        document.getElementById('result').textContent = JSON.stringify(out);
      }, 500);
    }
  }
  ready();
});
</script></body></html>)html");
  const std::string dom = dump_dom(file_url(dir / "drive.html"), dir, "--allow-file-access-from-files");
  const std::size_t open = dom.find("<pre id=\"result\">"), close = dom.find("</pre>", open);
  REQUIRE(open != std::string::npos);
  // The text of <pre> as serialized: &, < and > are character references.
  std::string text = dom.substr(open + 17, close - open - 17);
  for (const auto& [reference, character] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}}) {
    for (std::size_t at = text.find(reference); at != std::string::npos; at = text.find(reference, at + 1)) {
      text.replace(at, std::strlen(reference), character);
    }
  }
  INFO("result: " << text);
  REQUIRE(text != "pending");
  const nlohmann::json r = nlohmann::json::parse(text);
  CHECK(r["scriptError"].is_null());
  CHECK(r["blinkingAtStart"] == "on");
  // The link asks for 100 ms (the default is 500); the median of the ten gaps between eleven flips.
  // Chromium keeps an interval timer on its schedule, so a flip that comes late (a busy machine) makes one
  // long gap and one short one: single gaps prove nothing (a fixed 2 s count failed on a loaded machine,
  // the first ten gaps summed to 941 ms once on an idle one), their median stays at the interval unless
  // most flips come late. Between 50 and 250 ms: not the default's 500, not an unthrottled timer.
  REQUIRE(r["blinkFlipsTimed"] == 11);
  CHECK(r["medianGapMs"].get<double>() >= 50.0);
  CHECK(r["medianGapMs"].get<double>() <= 250.0);
  CHECK(r["blinkingAfterB"] == "off");
  CHECK(r["flipsWhilePaused"] == 1);  // only the flip of 't', none in the half second after
  CHECK(r["frameFlippedByT"] == true);
  CHECK(r["viewAfter2"] == "slider");
  CHECK(r["sliderShown"] == true);
  CHECK(r["currentAfterJ"] == 0);  // the first case, the failure
  CHECK(r["posAfterRight"] == "55");
  CHECK(r["viewAfter3"] == "blink");
  CHECK(r["viewAfter1"] == "side");
  CHECK(r["regionsHidden"] == true);
  CHECK(r["regionsShownAgain"] == true);
  CHECK(r["zoomRatio"] == 2);
  CHECK(r["zoomSelect"] == "2");
  CHECK(r["shownAfterFilter"] == "2");
  CHECK(r["passedHidden"] == true);
  CHECK(r["intervalShown"] == "100");
  CHECK(r["posAtDown"] == "20");
  CHECK(r["posAfterDrag"] == "80");
  CHECK(r["posAfterRelease"] == "80");  // moves after the button is released do not drag
  CHECK(r["clip"] == "inset(0px 20% 0px 0px)");
  CHECK_THAT(r["hash"].get<std::string>(),
             Catch::StartsWith("#view=slider&zoom=2&pos=80&blink=off&") &&
                 Catch::Contains("filter=error,failed,size-mismatch,new,missing"));
}
