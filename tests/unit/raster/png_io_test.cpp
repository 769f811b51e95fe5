// PNG I/O: round trips, every input format libpng can convert, and every way a file can be bad.
//
// Inputs in formats curvescan never writes (16-bit, grey, palette, interlaced) are written here with
// libpng directly, so the reader is checked against values computed independently in this file.
#include "curvescan/raster/png_io.h"

#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/pixel_format.h"
#include "scratch_directory.h"

namespace fs = std::filesystem;
using namespace curvescan;

namespace {

using test::ScratchDirectory;

std::vector<std::uint8_t> file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::vector<std::uint8_t>& bytes, std::size_t count) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(count));
}

// A random valid premultiplied image (r, g, b <= a); a quarter of the pixels opaque, some transparent.
Image random_premultiplied_image(int width, int height, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  Image image(width, height);
  for (Rgba8& p : image.pixels()) {
    const int kind = byte(rng) % 4;
    const int a = kind == 0 ? 255 : (kind == 1 ? 0 : byte(rng));
    std::uniform_int_distribution<int> channel(0, a);
    p = {static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(channel(rng)),
         static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(a)};
  }
  return image;
}

// Independent premultiplication for expected values: round(c·a/255), no ties since 255 is odd.
std::uint8_t premultiplied(int c, int a) {
  return static_cast<std::uint8_t>((c * a + 127) / 255);
}

// Writes a PNG of any libpng format from raw rows, so the tests can feed the reader what curvescan never
// writes. Errors abort the test through libpng's default handler (REQUIRE on the result).
struct RawPng {
  int width = 0, height = 0, bit_depth = 8, color_type = PNG_COLOR_TYPE_RGBA;
  int interlace = PNG_INTERLACE_NONE;
  std::vector<png_color> palette;
  std::vector<png_byte> palette_alpha;  // tRNS for palette images
  std::vector<std::vector<png_byte>> rows;
};

RawPng raw_png(int width, int height, int bit_depth, int color_type, int interlace = PNG_INTERLACE_NONE) {
  RawPng raw;
  raw.width = width;
  raw.height = height;
  raw.bit_depth = bit_depth;
  raw.color_type = color_type;
  raw.interlace = interlace;
  return raw;
}

bool write_raw_png(const RawPng& raw, const fs::path& path) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> row_pointers;
  for (const auto& row : raw.rows) row_pointers.push_back(const_cast<png_bytep>(row.data()));
  volatile bool ok = false;  // volatile: written after setjmp, read after a possible longjmp
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(raw.width), static_cast<png_uint_32>(raw.height),
                 raw.bit_depth, raw.color_type, raw.interlace, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!raw.palette.empty())
      png_set_PLTE(png, info, raw.palette.data(), static_cast<int>(raw.palette.size()));
    if (!raw.palette_alpha.empty()) {
      png_set_tRNS(png, info, raw.palette_alpha.data(), static_cast<int>(raw.palette_alpha.size()), nullptr);
    }
    png_write_info(png, info);
    png_write_image(png, row_pointers.data());
    png_write_end(png, nullptr);
    ok = true;
  }
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
  return ok;
}

// CRC-32 of PNG chunks (ISO 3309 polynomial, PNG spec section 5.5), bitwise: small inputs only.
std::uint32_t png_crc(const std::vector<std::uint8_t>& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (std::uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

void append_be32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void append_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  append_be32(out, static_cast<std::uint32_t>(data.size()));
  std::vector<std::uint8_t> typed(type, type + 4);
  typed.insert(typed.end(), data.begin(), data.end());
  out.insert(out.end(), typed.begin(), typed.end());
  append_be32(out, png_crc(typed));
}

// A PNG whose header claims width x height RGBA8 pixels, followed by an empty IDAT and IEND: enough for
// a reader to see the dimensions (and to fail later if it got past them).
std::vector<std::uint8_t> png_with_claimed_size(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> ihdr;
  append_be32(ihdr, width);
  append_be32(ihdr, height);
  ihdr.insert(ihdr.end(), {8, PNG_COLOR_TYPE_RGBA, 0, 0, 0});
  append_chunk(out, "IHDR", ihdr);
  append_chunk(out, "IDAT", {});
  append_chunk(out, "IEND", {});
  return out;
}

}  // namespace

TEST_CASE("premultiply then unpremultiply round trip is exact for every valid premultiplied pixel", "[png]") {
  // The justification of the exact PNG round trip below: unpremultiply gives u with |u - c·255/a| <= 1/2,
  // so |u·a/255 - c| <= a/510 < 1/2 for a < 255, and premultiply's rounding to nearest returns c. At
  // a = 255 both maps are the identity. Checked here for every (c, a) with c <= a.
  for (int a = 0; a <= 255; ++a) {
    for (int c = 0; c <= a; ++c) {
      const auto ca = static_cast<std::uint8_t>(c), aa = static_cast<std::uint8_t>(a);
      const Rgba8 p{ca, ca, ca, aa};
      REQUIRE(premultiply(unpremultiply(p)) == p);
    }
  }
}

TEST_CASE("write_png then read_png returns random premultiplied images exactly", "[png]") {
  // Exact, not within a tolerance: see the previous test for why the unpremultiply rounding is undone.
  ScratchDirectory dir{"png-test"};
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    const int width = 1 + static_cast<int>(seed * 7 % 40), height = 1 + static_cast<int>(seed * 13 % 30);
    const Image image = random_premultiplied_image(width, height, seed);
    const fs::path path = dir / ("round_trip_" + std::to_string(seed) + ".png");
    REQUIRE(write_png(image, path).is_ok());
    const Result<Image> back = read_png(path);
    REQUIRE(back.is_ok());
    CHECK(back->width() == width);
    CHECK(back->height() == height);
    CHECK(*back == image);
  }
  // Nothing but the PNGs is left in the directory: the temporaries were renamed.
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 6);
}

TEST_CASE("write_png stores straight alpha as PNG requires", "[png]") {
  ScratchDirectory dir{"png-test"};
  Image image(1, 1);
  image.at(0, 0) = {64, 32, 0, 128};  // premultiplied: straight (128, 64, 0, 128) after c·255/a rounding
  REQUIRE(write_png(image, dir / "straight.png").is_ok());

  std::FILE* file = std::fopen((dir / "straight.png").c_str(), "rb");
  REQUIRE(file != nullptr);
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_byte pixel[4] = {};
  volatile png_byte color_type = 0, bit_depth = 0;  // volatile: set after setjmp, read after longjmp
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, file);
    png_read_info(png, info);
    color_type = png_get_color_type(png, info);
    bit_depth = png_get_bit_depth(png, info);
    png_read_row(png, pixel, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  CHECK(color_type == PNG_COLOR_TYPE_RGBA);
  CHECK(bit_depth == 8);
  CHECK(pixel[0] == (64 * 255 + 64) / 128);  // round(64·255/128) = round(127.5) = 128, half up
  CHECK(pixel[1] == (32 * 255 + 64) / 128);
  CHECK(pixel[2] == 0);
  CHECK(pixel[3] == 128);
}

TEST_CASE("read_png converts 16-bit RGBA with rounding and premultiplies", "[png]") {
  ScratchDirectory dir{"png-test"};
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> sample(0, 65535);
  RawPng raw = raw_png(9, 4, 16, PNG_COLOR_TYPE_RGBA);
  std::vector<std::uint16_t> values;
  for (int y = 0; y < raw.height; ++y) {
    std::vector<png_byte> row;
    for (int i = 0; i < raw.width * 4; ++i) {
      const auto v = static_cast<std::uint16_t>(sample(rng));
      values.push_back(v);
      row.push_back(static_cast<png_byte>(v >> 8));  // PNG samples are big-endian
      row.push_back(static_cast<png_byte>(v & 0xff));
    }
    raw.rows.push_back(row);
  }
  REQUIRE(write_raw_png(raw, dir / "rgba16.png"));
  const Result<Image> image = read_png(dir / "rgba16.png");
  REQUIRE(image.is_ok());
  // v·255/65535 = v/257 never lies halfway between integers, so round-half-up is round-to-nearest.
  const auto to8 = [](int v) { return (v * 255 + 32767) / 65535; };
  for (int y = 0; y < raw.height; ++y) {
    for (int x = 0; x < raw.width; ++x) {
      const std::size_t i = 4 * static_cast<std::size_t>(y * raw.width + x);
      const int a = to8(values[i + 3]);
      const Rgba8 expected{premultiplied(to8(values[i]), a), premultiplied(to8(values[i + 1]), a),
                           premultiplied(to8(values[i + 2]), a), static_cast<std::uint8_t>(a)};
      CHECK(image->at(x, y) == expected);
    }
  }
}

TEST_CASE("read_png expands grey of every bit depth to opaque RGB", "[png]") {
  ScratchDirectory dir{"png-test"};
  for (int bit_depth : {1, 2, 4, 8, 16}) {
    CAPTURE(bit_depth);
    const int max_sample = (1 << bit_depth) - 1;
    RawPng raw = raw_png(16, 2, bit_depth, PNG_COLOR_TYPE_GRAY);
    std::vector<int> samples;
    for (int y = 0; y < raw.height; ++y) {
      // Pack samples most significant bit first (PNG spec 7.2); 16-bit samples are two bytes.
      std::vector<png_byte> row(static_cast<std::size_t>((raw.width * bit_depth + 7) / 8), 0);
      for (int x = 0; x < raw.width; ++x) {
        const int s = (x * 37 + y * 11) % (max_sample + 1);
        samples.push_back(s);
        if (bit_depth == 16) {
          row[static_cast<std::size_t>(2 * x)] = static_cast<png_byte>(s >> 8);
          row[static_cast<std::size_t>(2 * x + 1)] = static_cast<png_byte>(s & 0xff);
        } else {
          const int bit = x * bit_depth;
          row[static_cast<std::size_t>(bit / 8)] |= static_cast<png_byte>(s << (8 - bit_depth - bit % 8));
        }
      }
      raw.rows.push_back(row);
    }
    const fs::path path = dir / ("grey" + std::to_string(bit_depth) + ".png");
    REQUIRE(write_raw_png(raw, path));
    const Result<Image> image = read_png(path);
    REQUIRE(image.is_ok());
    for (int y = 0; y < raw.height; ++y) {
      for (int x = 0; x < raw.width; ++x) {
        // Low depths scale by replication (PNG spec 13.12: s·255/max is exact for 1, 2, 4 bits).
        const int s = samples[static_cast<std::size_t>(y * raw.width + x)];
        const auto v = static_cast<std::uint8_t>((s * 255 + max_sample / 2) / max_sample);
        CHECK(image->at(x, y) == Rgba8{v, v, v, 255});
      }
    }
  }
}

TEST_CASE("read_png converts grey with alpha and premultiplies", "[png]") {
  ScratchDirectory dir{"png-test"};
  RawPng raw = raw_png(4, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA);
  raw.rows = {{200, 255, 200, 128, 17, 0, 255, 1}};
  REQUIRE(write_raw_png(raw, dir / "grey_alpha.png"));
  const Result<Image> image = read_png(dir / "grey_alpha.png");
  REQUIRE(image.is_ok());
  for (int x = 0; x < 4; ++x) {
    const int g = raw.rows[0][static_cast<std::size_t>(2 * x)],
              a = raw.rows[0][static_cast<std::size_t>(2 * x + 1)];
    const std::uint8_t c = premultiplied(g, a);
    CHECK(image->at(x, 0) == Rgba8{c, c, c, static_cast<std::uint8_t>(a)});
  }
}

TEST_CASE("read_png expands a palette with tRNS transparency", "[png]") {
  ScratchDirectory dir{"png-test"};
  RawPng raw = raw_png(5, 2, 4, PNG_COLOR_TYPE_PALETTE);
  raw.palette = {{255, 0, 0}, {0, 255, 0}, {10, 20, 30}, {250, 128, 7}};
  raw.palette_alpha = {255, 0, 77};  // entry 3 has no tRNS value: opaque (PNG spec 11.3.2.1)
  const int indices[2][5] = {{0, 1, 2, 3, 2}, {3, 3, 0, 1, 2}};
  for (const auto& index_row : indices) {
    std::vector<png_byte> row(3, 0);
    for (int x = 0; x < 5; ++x) {
      row[static_cast<std::size_t>(x / 2)] |= static_cast<png_byte>(index_row[x] << (x % 2 == 0 ? 4 : 0));
    }
    raw.rows.push_back(row);
  }
  REQUIRE(write_raw_png(raw, dir / "palette.png"));
  const Result<Image> image = read_png(dir / "palette.png");
  REQUIRE(image.is_ok());
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 5; ++x) {
      const auto index = static_cast<std::size_t>(indices[y][x]);
      const png_color c = raw.palette[index];
      const int a = index < raw.palette_alpha.size() ? raw.palette_alpha[index] : 255;
      CHECK(image->at(x, y) == Rgba8{premultiplied(c.red, a), premultiplied(c.green, a),
                                     premultiplied(c.blue, a), static_cast<std::uint8_t>(a)});
    }
  }
}

TEST_CASE("read_png deinterlaces Adam7 RGB", "[png]") {
  ScratchDirectory dir{"png-test"};
  RawPng raw = raw_png(13, 11, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7);
  for (int y = 0; y < raw.height; ++y) {
    std::vector<png_byte> row;
    for (int x = 0; x < raw.width; ++x) {
      row.insert(row.end(), {static_cast<png_byte>(x * 19), static_cast<png_byte>(y * 23),
                             static_cast<png_byte>((x * y) % 256)});
    }
    raw.rows.push_back(row);
  }
  REQUIRE(write_raw_png(raw, dir / "adam7.png"));
  const Result<Image> image = read_png(dir / "adam7.png");
  REQUIRE(image.is_ok());
  for (int y = 0; y < raw.height; ++y) {
    for (int x = 0; x < raw.width; ++x) {
      const Rgba8 expected{static_cast<std::uint8_t>(x * 19), static_cast<std::uint8_t>(y * 23),
                           static_cast<std::uint8_t>((x * y) % 256), 255};
      CHECK(image->at(x, y) == expected);
    }
  }
}

TEST_CASE("read_png reports a file truncated at any length as corrupt", "[png]") {
  ScratchDirectory dir{"png-test"};
  const fs::path whole = dir / "whole.png";
  REQUIRE(write_png(random_premultiplied_image(6, 5, 99), whole).is_ok());
  const std::vector<std::uint8_t> bytes = file_bytes(whole);
  REQUIRE(bytes.size() > 40);
  const fs::path cut = dir / "cut.png";
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    CAPTURE(length);
    write_bytes(cut, bytes, length);
    const Result<Image> image = read_png(cut);
    REQUIRE_FALSE(image.is_ok());
    CHECK(image.error().kind == ErrorKind::kCorruptInput);
    CHECK(image.error().message.find(cut.string()) != std::string::npos);
  }
  write_bytes(cut, bytes, 20);  // inside IHDR: the message says truncated
  CHECK_THAT(read_png(cut).error().message, Catch::Contains("truncated"));
}

TEST_CASE("read_png rejects empty files, garbage, bad CRCs and a missing file with clear errors", "[png]") {
  ScratchDirectory dir{"png-test"};
  const fs::path path = dir / "bad.png";

  write_bytes(path, {}, 0);
  CHECK_THAT(read_png(path).error().message, Catch::Contains("empty"));

  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  const std::vector<std::uint8_t> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::uint8_t> garbage(static_cast<std::size_t>(1 + trial * 13));
    for (auto& b : garbage) b = static_cast<std::uint8_t>(byte(rng));
    // Half the trials start with a valid signature so that libpng's chunk parser meets the garbage.
    if (trial % 2 == 1) garbage.insert(garbage.begin(), signature.begin(), signature.end());
    write_bytes(path, garbage, garbage.size());
    const Result<Image> image = read_png(path);
    REQUIRE_FALSE(image.is_ok());
    CHECK(image.error().kind == ErrorKind::kCorruptInput);
    if (trial % 2 == 0) CHECK_THAT(image.error().message, Catch::Contains("not a PNG"));
  }

  REQUIRE(write_png(random_premultiplied_image(3, 3, 5), path).is_ok());
  std::vector<std::uint8_t> bytes = file_bytes(path);
  bytes[8 + 8 + 13] ^= 0x01;  // first byte of IHDR's CRC: signature (8), length and type (8), data (13)
  write_bytes(path, bytes, bytes.size());
  const Result<Image> bad_crc = read_png(path);
  REQUIRE_FALSE(bad_crc.is_ok());
  CHECK(bad_crc.error().kind == ErrorKind::kCorruptInput);
  CHECK_THAT(bad_crc.error().message, Catch::Contains("CRC"));

  const Result<Image> missing = read_png(dir / "no_such_file.png");
  REQUIRE_FALSE(missing.is_ok());
  CHECK(missing.error().kind == ErrorKind::kIoError);
  CHECK_THAT(missing.error().message, Catch::Contains("no_such_file.png"));
}

TEST_CASE("read_png refuses absurd dimensions before allocating", "[png]") {
  ScratchDirectory dir{"png-test"};
  const fs::path path = dir / "huge.png";
  // 100000 per side exceeds kMaxImageDimension; 30000 x 30000 is within it per side but 9e8 pixels
  // exceeds kMaxImagePixels. Either would need gigabytes if the reader allocated first (ASan would fail
  // the test run on such an allocation); the file holds no pixel data at all.
  for (auto [width, height] :
       {std::pair<std::uint32_t, std::uint32_t>{100000, 100000}, {30000, 30000}, {1, 0x7fffffffu}}) {
    CAPTURE(width, height);
    const std::vector<std::uint8_t> bytes = png_with_claimed_size(width, height);
    write_bytes(path, bytes, bytes.size());
    const Result<Image> image = read_png(path);
    REQUIRE_FALSE(image.is_ok());
    CHECK(image.error().kind == ErrorKind::kLimitExceeded);
    CHECK_THAT(image.error().message, Catch::Contains("limit"));
  }
  // Control: the same construction within the limits gets past the size check and fails on the empty IDAT.
  const std::vector<std::uint8_t> small = png_with_claimed_size(4, 4);
  write_bytes(path, small, small.size());
  const Result<Image> image = read_png(path);
  REQUIRE_FALSE(image.is_ok());
  CHECK(image.error().kind == ErrorKind::kCorruptInput);
}

TEST_CASE("a failed write_png leaves an existing file untouched and no temporary behind", "[png]") {
  ScratchDirectory dir{"png-test"};
  const Image original = random_premultiplied_image(4, 4, 11);
  const Image replacement = random_premultiplied_image(4, 4, 12);

  SECTION("the temporary's name is too long for the file system") {
    // NAME_MAX is 255 on Linux file systems; the destination fits, the temporary (name + ".tmp-...") not.
    const fs::path path = dir / (std::string(250, 'x') + ".png");
    REQUIRE(write_png(original, dir / "short.png").is_ok());  // write_png cannot make it under this name
    fs::rename(dir / "short.png", path);
    const std::vector<std::uint8_t> before = file_bytes(path);
    const Status status = write_png(replacement, path);
    REQUIRE_FALSE(status.is_ok());
    CHECK(status.error().kind == ErrorKind::kIoError);
    CHECK(file_bytes(path) == before);
  }
  SECTION("the directory is not writable") {
    const fs::path path = dir / "kept.png";
    REQUIRE(write_png(original, path).is_ok());
    const std::vector<std::uint8_t> before = file_bytes(path);
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    const Status status = write_png(replacement, path);
    fs::permissions(dir.path(), fs::perms::owner_all);
    if (::geteuid() == 0) {
      WARN("running as root: directory permissions do not stop writes, only the untouched-file check runs");
    } else {
      REQUIRE_FALSE(status.is_ok());
      CHECK(status.error().kind == ErrorKind::kIoError);
      CHECK(file_bytes(path) == before);
    }
  }
  SECTION("the destination is a directory, so the final rename fails after the data was written") {
    const fs::path path = dir / "a_directory.png";
    fs::create_directory(path);
    std::ofstream(path / "inside.txt") << "keep me";
    const Status status = write_png(replacement, path);
    REQUIRE_FALSE(status.is_ok());
    CHECK(status.error().kind == ErrorKind::kIoError);
    CHECK(fs::is_directory(path));
    CHECK(fs::exists(path / "inside.txt"));
  }
  SECTION("the image is empty") {
    const fs::path path = dir / "kept.png";
    REQUIRE(write_png(original, path).is_ok());
    const std::vector<std::uint8_t> before = file_bytes(path);
    const Status status = write_png(Image(), path);
    REQUIRE_FALSE(status.is_ok());
    CHECK(status.error().kind == ErrorKind::kInvalidArgument);
    CHECK(file_bytes(path) == before);
  }
  // In every case only the files the section made remain: no "*.tmp-*" survives a failure.
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
  }
}

// ---- in memory: encode_png and decode_png -----------------------------------------------------------------

TEST_CASE("encode_png then decode_png returns random premultiplied images exactly", "[png]") {
  // Exact equality, no tolerance: every premultiplied pixel survives unpremultiply + premultiply (the
  // round-trip test above checks all of them), and PNG itself is lossless.
  for (const auto& [width, height, seed] : {std::tuple{1, 1, 1u}, std::tuple{7, 3, 2u}, std::tuple{64, 33, 3u}}) {
    CAPTURE(width, height);
    const Image image = random_premultiplied_image(width, height, seed);
    const Result<std::vector<std::uint8_t>> bytes = encode_png(image);
    REQUIRE(bytes.is_ok());
    const Result<Image> decoded = decode_png(*bytes);
    REQUIRE(decoded.is_ok());
    CHECK(*decoded == image);
  }
}

TEST_CASE("encode_png makes the same bytes write_png writes to a file", "[png]") {
  ScratchDirectory dir{"png-test"};
  const Image image = random_premultiplied_image(9, 5, 17);
  REQUIRE(write_png(image, dir / "file.png").is_ok());
  const Result<std::vector<std::uint8_t>> bytes = encode_png(image);
  REQUIRE(bytes.is_ok());
  CHECK(*bytes == file_bytes(dir / "file.png"));
}

TEST_CASE("encode_png refuses an empty image", "[png]") {
  const Result<std::vector<std::uint8_t>> bytes = encode_png(Image());
  REQUIRE_FALSE(bytes.is_ok());
  CHECK(bytes.error().kind == ErrorKind::kInvalidArgument);
}

TEST_CASE("decode_png reports empty, non-PNG, cut and oversized data with clear errors", "[png]") {
  const Result<std::vector<std::uint8_t>> whole = encode_png(random_premultiplied_image(6, 5, 99));
  REQUIRE(whole.is_ok());
  const std::vector<std::uint8_t>& bytes = *whole;

  const Result<Image> empty = decode_png({});
  REQUIRE_FALSE(empty.is_ok());
  CHECK(empty.error().kind == ErrorKind::kCorruptInput);
  CHECK_THAT(empty.error().message, Catch::Contains("empty"));

  const std::vector<std::uint8_t> text = {'<', 's', 'v', 'g', '/', '>', ' ', ' ', ' '};
  CHECK_THAT(decode_png(text).error().message, Catch::Contains("not a PNG file"));

  for (std::size_t length = 8; length < bytes.size(); ++length) {
    CAPTURE(length);
    const Result<Image> cut = decode_png(std::span(bytes.data(), length));
    REQUIRE_FALSE(cut.is_ok());
    CHECK(cut.error().kind == ErrorKind::kCorruptInput);
  }
  CHECK_THAT(decode_png(std::span(bytes.data(), 20)).error().message, Catch::Contains("truncated"));

  // 6 x 5 = 30 pixels: a limit of 29 refuses it before decoding, 30 accepts it.
  const Result<Image> over = decode_png(bytes, 29);
  REQUIRE_FALSE(over.is_ok());
  CHECK(over.error().kind == ErrorKind::kLimitExceeded);
  CHECK_THAT(over.error().message, Catch::Contains("29 pixels"));
  CHECK(decode_png(bytes, 30).is_ok());
}

TEST_CASE("read_png stops at its size bound, also on a device that never ends", "[png]") {
  ScratchDirectory dir{"png-test"};
  const Result<std::vector<std::uint8_t>> bytes = encode_png(random_premultiplied_image(6, 5, 4));
  REQUIRE(bytes.is_ok());
  write_bytes(dir / "a.png", *bytes, bytes->size());
  CHECK(read_png(dir / "a.png", bytes->size()).is_ok());  // exactly the bound is allowed
  const Result<Image> over = read_png(dir / "a.png", bytes->size() - 1);
  REQUIRE_FALSE(over.is_ok());
  CHECK(over.error().kind == ErrorKind::kLimitExceeded);
  if (fs::exists("/dev/zero")) {
    // /dev/zero has no size and no end: only the bound stops the read (1 MiB here).
    const Result<Image> zero = read_png("/dev/zero", std::size_t{1} << 20);
    REQUIRE_FALSE(zero.is_ok());
    CHECK(zero.error().kind == ErrorKind::kLimitExceeded);
    CHECK_THAT(zero.error().message, Catch::Contains("larger than 1 MiB"));
  }
}
