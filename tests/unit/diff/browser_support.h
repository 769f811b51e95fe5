// Headless Chromium for the report tests: the DOM after the page's scripts ran (--dump-dom) and
// screenshots (--screenshot) read back as images, plus the small pixel searches the screenshot tests make.
//
// Chromium is a required test dependency (build.sh installs the Debian package): without it these tests
// fail, they do not skip. Every run is bounded by `timeout`, uses its own profile directory, and maps
// every host name to nothing, so a page that tried to fetch anything from the network would show it.
#pragma once

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"
#include "diff_test_support.h"

namespace curvescan::test {

inline constexpr const char* kChromium = "/usr/bin/chromium";

/// The command line common to every run; `extra` adds flags.
inline std::string chromium_command(const ScratchDirectory& scratch, const std::string& extra) {
  static int runs = 0;
  const std::filesystem::path profile = scratch / ("chromium-profile-" + std::to_string(++runs));
  std::filesystem::create_directories(profile);
  return "timeout 120 " + std::string(kChromium) +
         " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --hide-scrollbars"
         " --disable-background-networking --disable-component-update --disable-sync"
         " --host-resolver-rules='MAP * ~NOTFOUND' --force-device-scale-factor=1"
         " --user-data-dir=" +
         shell_quote(profile.string()) + " --enable-logging=stderr --v=0 " + extra;
}

/// The file:// URL of `html` (absolute), with an optional fragment (without the '#').
inline std::string file_url(const std::filesystem::path& html, const std::string& fragment = "") {
  return "file://" + relative_url(std::filesystem::absolute(html)) + (fragment.empty() ? "" : "#" + fragment);
}

/// The DOM of the page after its load event and up to 10 s of virtual time for its timers.
inline std::string dump_dom(const std::string& url, const ScratchDirectory& scratch,
                            const std::string& extra = "") {
  const CommandOutput out = run_shell(
      chromium_command(scratch, extra + " --virtual-time-budget=10000 --dump-dom " + shell_quote(url)),
      scratch.path());
  INFO("chromium stderr: " << out.err);
  REQUIRE(out.exit_code == 0);
  return out.out;
}

/// A screenshot of the page in a window of width x height CSS pixels (device scale 1), after its load
/// event and its scripts (up to 5 s of virtual time).
inline Image screenshot(const std::string& url, const ScratchDirectory& scratch, int width, int height) {
  static int shots = 0;
  const std::filesystem::path png = scratch / ("screenshot-" + std::to_string(++shots) + ".png");
  const CommandOutput out = run_shell(
      chromium_command(scratch, "--virtual-time-budget=5000 --window-size=" + std::to_string(width) + "," +
                                    std::to_string(height) + " --screenshot=" + shell_quote(png.string()) +
                                    " " + shell_quote(url)),
      scratch.path());
  INFO("chromium stderr: " << out.err);
  REQUIRE(out.exit_code == 0);
  Result<Image> image = read_png(png);
  REQUIRE(image.is_ok());
  REQUIRE(image->width() == width);
  return std::move(*image);
}

inline std::string body_attribute(const std::string& dom, const std::string& name) {
  const std::regex pattern("<body[^>]*\\s" + name + "=\"([^\"]*)\"");
  std::smatch match;
  return std::regex_search(dom, match, pattern) ? match[1].str() : std::string("<absent>");
}

/// Within `tolerance` levels of `colour` on each of R, G and B (screenshots are opaque).
inline std::function<bool(Rgba8)> near(Rgba8 colour, int tolerance) {
  return [=](Rgba8 p) {
    return std::abs(p.r - colour.r) <= tolerance && std::abs(p.g - colour.g) <= tolerance &&
           std::abs(p.b - colour.b) <= tolerance;
  };
}

inline std::size_t count_pixels(const Image& image, const std::function<bool(Rgba8)>& wanted) {
  std::size_t count = 0;
  for (const Rgba8& p : image.pixels()) count += wanted(p) ? 1 : 0;
  return count;
}

/// The boxes of the 8-connected clusters of wanted pixels, top to bottom, then left to right.
inline std::vector<PixelBox> clusters(const Image& image, const std::function<bool(Rgba8)>& wanted) {
  const int w = image.width(), h = image.height();
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  std::vector<PixelBox> boxes;
  for (int y0 = 0; y0 < h; ++y0) {
    for (int x0 = 0; x0 < w; ++x0) {
      const std::size_t start = static_cast<std::size_t>(y0) * static_cast<std::size_t>(w) + x0;
      if (seen[start] || !wanted(image.at(x0, y0))) continue;
      int min_x = x0, max_x = x0, min_y = y0, max_y = y0;
      std::vector<std::pair<int, int>> stack = {{x0, y0}};
      seen[start] = 1;
      while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        min_x = std::min(min_x, x);
        max_x = std::max(max_x, x);
        min_y = std::min(min_y, y);
        max_y = std::max(max_y, y);
        for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny) {
          for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) {
            const std::size_t i = static_cast<std::size_t>(ny) * static_cast<std::size_t>(w) + nx;
            if (seen[i] || !wanted(image.at(nx, ny))) continue;
            seen[i] = 1;
            stack.emplace_back(nx, ny);
          }
        }
      }
      boxes.push_back({min_x, min_y, max_x - min_x + 1, max_y - min_y + 1});
    }
  }
  std::sort(boxes.begin(), boxes.end(),
            [](const PixelBox& a, const PixelBox& b) { return std::tie(a.y, a.x) < std::tie(b.y, b.x); });
  return boxes;
}

}  // namespace curvescan::test
