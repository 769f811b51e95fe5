// Helpers shared by the image-diff tests: synthetic images, scratch directories, PNG files written with
// libpng directly (so the tests do not depend on the writer under test), and running the curvescan binary.
#pragma once

#include <png.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "curvescan/raster/image.h"
#include "run_command.h"

namespace curvescan::test {

/// A width x height image filled with one premultiplied pixel.
inline Image filled(int width, int height, Rgba8 pixel) {
  Image image(width, height);
  for (Rgba8& p : image.pixels()) p = pixel;
  return image;
}

/// Paints the rectangle [x0, x1) x [y0, y1) of `image` with `pixel`.
inline void paint(Image& image, int x0, int y0, int x1, int y1, Rgba8 pixel) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) image.at(x, y) = pixel;
  }
}

/// Writes a PNG with libpng's simplified API-free low-level calls: `rows` holds the raw samples of each
/// row in the layout of `colour_type` and `bit_depth` (16-bit samples big-endian, as PNG stores them).
/// `palette`/`transparency` are used for PNG_COLOR_TYPE_PALETTE.
inline bool write_raw_png(const std::filesystem::path& path, int width, int height, int bit_depth,
                          int colour_type, const std::vector<std::vector<unsigned char>>& rows,
                          const std::vector<png_color>& palette = {},
                          const std::vector<unsigned char>& transparency = {}) {
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bit_depth,
               colour_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
  if (!transparency.empty()) {
    png_set_tRNS(png, info, transparency.data(), static_cast<int>(transparency.size()), nullptr);
  }
  png_write_info(png, info);
  for (const auto& row : rows) png_write_row(png, row.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(file) == 0;
}

/// Straight 8-bit RGBA rows of `image`'s premultiplied pixels, colour bits of transparent pixels set to
/// `junk` (PNG writers often leave garbage there).
inline std::vector<std::vector<unsigned char>> straight_rows(const Image& image, unsigned char junk = 0) {
  std::vector<std::vector<unsigned char>> rows;
  for (int y = 0; y < image.height(); ++y) {
    std::vector<unsigned char> row;
    for (int x = 0; x < image.width(); ++x) {
      const Rgba8 p = image.at(x, y);
      const auto straight = [&](int c) {
        return p.a == 0 ? junk : static_cast<unsigned char>((c * 255 + p.a / 2) / p.a);
      };
      row.insert(row.end(), {straight(p.r), straight(p.g), straight(p.b), p.a});
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

/// Runs `curvescan diff <arguments>` (arguments already shell-quoted where needed).
inline CommandOutput run_diff(const std::string& arguments, const std::filesystem::path& scratch) {
  return run_shell(shell_quote(curvescan_binary()) + " diff " + arguments, scratch);
}

}  // namespace curvescan::test
