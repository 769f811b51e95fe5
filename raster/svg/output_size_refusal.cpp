// The canvas of an output size, or the message refusing it (output_size_refusal.h).
#include "output_size_refusal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "curvescan/raster/limits.h"

namespace curvescan::svg::detail {
namespace {

// A side in pixels as the user reads it: whole below 1e15, exponent form above (a width of 1e308 has
// 309 digits).
std::string pixels_text(double value) {
  char text[64];
  std::snprintf(text, sizeof text, std::fabs(value) < 1e15 ? "%.0f" : "%.3g", value);
  return text;
}

// 10^log10_value in the exponent form of "%.3g", for values beyond a double.
std::string exponent_form(double log10_value) {
  double exponent = std::floor(log10_value);
  char mantissa[32];
  std::snprintf(mantissa, sizeof mantissa, "%.3g", std::pow(10.0, log10_value - exponent));
  if (std::strtod(mantissa, nullptr) >= 10.0) {  // 9.9996 rounds to 10
    exponent += 1.0;
    std::snprintf(mantissa, sizeof mantissa, "%.3g", std::pow(10.0, log10_value - exponent));
  }
  return std::string(mantissa) + "e+" + std::to_string(static_cast<long long>(exponent));
}

// An option's value as given (px, a factor, dpi).
std::string given_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// log10 of the drawn size's sides, finite where they are beyond a double; NaN where even the scaled
// computation has none (a natural size that underflows once scaled).
OutputSize drawn_log10(const OutputSizeRequest& request) {
  const std::optional<ScaledOutputSize> scaled = output_size_scaled(request);
  if (!scaled || !(scaled->size.width > 0.0) || !(scaled->size.height > 0.0))
    return {std::nan(""), std::nan("")};
  const double shift = scaled->exponent * std::numbers::log10e * std::numbers::ln2;  // log10 of 2^exponent
  return {std::log10(scaled->size.width) + shift, std::log10(scaled->size.height) + shift};
}

// What the size came from: the natural size and every option that changes it, with their values.
std::string sources_text(const OutputSizeAsked& asked) {
  const OutputSizeRequest& r = asked.request;
  std::string text = std::string(asked.exported ? "the element's size " : "the document's size ") +
                     given_text(r.natural_width) + " x " + given_text(r.natural_height) + " px";
  if (asked.dpi_x != 96.0 || asked.dpi_y != 96.0) {
    text += asked.dpi_x == asked.dpi_y
                ? " at --dpi " + given_text(asked.dpi_x)
                : " at -d " + given_text(asked.dpi_x) + " -p " + given_text(asked.dpi_y);
  }
  if (r.width) text += ", -w " + given_text(*r.width) + " px";
  if (r.height) text += ", -h " + given_text(*r.height) + " px";
  if (asked.zoom != 1.0) text += ", -z " + given_text(asked.zoom);
  if (asked.x_zoom != 1.0) text += ", -x " + given_text(asked.x_zoom);
  if (asked.y_zoom != 1.0) text += ", -y " + given_text(asked.y_zoom);
  if (asked.page_width) text += ", --page-width " + given_text(*asked.page_width) + " px";
  if (asked.page_height) text += ", --page-height " + given_text(*asked.page_height) + " px";
  return text;
}

}  // namespace

Result<OutputPixels> output_pixels(const OutputSizeAsked& asked, const OutputSize& drawn) {
  // Round up as rsvg-convert does; 1e-9 absorbs the rounding of a product meant to be an integer.
  const double pixels_x = std::ceil(asked.page_width.value_or(drawn.width) - 1e-9);
  const double pixels_y = std::ceil(asked.page_height.value_or(drawn.height) - 1e-9);
  const double largest = kMaxImageDimension;
  if (pixels_x >= 1.0 && pixels_y >= 1.0 && pixels_x <= largest && pixels_y <= largest &&
      pixels_x * pixels_y <= static_cast<double>(asked.max_pixels)) {
    return OutputPixels{static_cast<int>(pixels_x), static_cast<int>(pixels_y)};
  }

  // The sides as text, and whether each is beyond the largest side; a side past a double comes from the
  // scaled computation.
  const OutputSize logs = drawn_log10(asked.request);
  const auto side = [&](double pixels, double log10_pixels, bool page) {
    if (page || std::isfinite(pixels)) return pixels_text(pixels > 0.0 ? pixels : 0.0);  // no "-0"
    return std::isfinite(log10_pixels) ? exponent_form(log10_pixels) : std::string("more than 1e+308");
  };
  const bool page_x = asked.page_width.has_value(), page_y = asked.page_height.has_value();
  const bool huge_x = !(page_x || std::isfinite(pixels_x)) || pixels_x > largest;
  const bool huge_y = !(page_y || std::isfinite(pixels_y)) || pixels_y > largest;
  const std::string size = side(pixels_x, logs.width, page_x) + " x " + side(pixels_y, logs.height, page_y);
  const std::string what = "the output would be " + size + " pixels (" + sources_text(asked) + ")";
  const std::string options = page_x || page_y ? "--page-width and --page-height" : "-w, -h or -z";

  if (!(pixels_x >= 1.0 && pixels_y >= 1.0) && !huge_x && !huge_y) {
    return Error{ErrorKind::kLimitExceeded,
                 what + ": an image is at least 1 pixel wide and tall; give a larger " + options};
  }
  if (huge_x || huge_y) {
    return Error{ErrorKind::kLimitExceeded, what + ", beyond the limit of " +
                                                std::to_string(kMaxImageDimension) +
                                                " pixels per side: give a smaller " + options};
  }
  const double area = pixels_x * pixels_y;  // both sides at most 32767: exact in a double
  // --max-pixels is offered only where raising it can make the canvas: at most kMaxImagePixels.
  const std::string most = std::to_string(kMaxImagePixels);
  const std::string advice =
      area <= static_cast<double>(kMaxImagePixels)
          ? "raise it with --max-pixels, up to " + most + ", or give a smaller " + options
      : asked.max_pixels < kMaxImagePixels ? "--max-pixels goes up to " + most + "; give a smaller " + options
                                           : "give a smaller " + options;
  return Error{ErrorKind::kLimitExceeded, what + ", " + pixels_text(area) + " in all, beyond the limit of " +
                                              std::to_string(asked.max_pixels) + " pixels (" + advice + ")"};
}

}  // namespace curvescan::svg::detail
