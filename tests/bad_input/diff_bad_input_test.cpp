// `curvescan diff` on bad PNG input: empty, truncated at many offsets (inside the signature, inside IHDR,
// inside IDAT, before IEND), corrupted (CRC, compressed data, header fields), absurd sizes, wrong types,
// garbage and unwritable outputs. Each: exit 3, one line naming the file and the problem, and the diff
// image (-o) neither made nor touched (bad_input_case.h).
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bad_input_case.h"
#include "curvescan/raster/png_io.h"

namespace curvescan::test {
namespace {

// A 48 x 40 seeded-noise PNG written by curvescan itself: noise keeps IDAT long enough to cut inside it.
std::string noise_png() {
  Image image(48, 40);
  std::mt19937 random(48);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const auto v = static_cast<std::uint8_t>(random() & 0xff);
      image.at(x, y) = Rgba8{v, v, v, 255};
    }
  }
  const auto dir = scratch_directory("bad-input-png");
  REQUIRE(write_png(image, dir / "noise.png").is_ok());
  std::string bytes = read_text(dir / "noise.png");
  return bytes;
}

// CRC-32 of PNG chunks (ISO 3309, as the PNG specification section 5.5 defines it), bit by bit.
std::uint32_t png_crc(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const char c : bytes) {
    crc ^= static_cast<std::uint8_t>(c);
    for (int k = 0; k < 8; ++k) crc = (crc & 1u) ? (crc >> 1) ^ 0xedb88320u : crc >> 1;
  }
  return crc ^ 0xffffffffu;
}

void put_be32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (24 - 8 * i)) & 0xff);
}

// The PNG with IHDR's fields changed (offsets of the PNG specification 11.2.2: width at 16, height at 20,
// bit depth at 24, colour type at 25) and its CRC recomputed, so only the changed field is wrong.
std::string with_header(std::string png, std::uint32_t width, std::uint32_t height, int bit_depth = 8,
                        int colour_type = 6) {
  put_be32(png, 16, width);
  put_be32(png, 20, height);
  png[24] = static_cast<char>(bit_depth);
  png[25] = static_cast<char>(colour_type);
  put_be32(png, 29, png_crc(png.substr(12, 17)));  // chunk type + 13 data bytes
  return png;
}

std::string seeded_garbage(unsigned seed, std::size_t size) {
  std::mt19937 random(seed);
  std::string bytes(size, '\0');
  for (char& c : bytes) c = static_cast<char>(random() & 0xff);
  return bytes;
}

TEST_CASE("diff: truncated, corrupt, absurd and wrong-type PNG inputs are one clear error", "[bad_input][diff]") {
  const std::string good = noise_png();
  const std::size_t idat = good.find("IDAT");
  const std::size_t iend = good.find("IEND");
  REQUIRE(idat != std::string::npos);
  REQUIRE(iend != std::string::npos);
  const std::string kRead = "cannot read '[^']*input'";
  const std::string kArguments = "diff {in} {dir}/good.png -o {out}";
  std::vector<BadInputCase> cases;
  const auto add = [&](const std::string& name, const std::string& input, const std::string& message) {
    BadInputCase c{name, kArguments, input, 3, message};
    c.extra_files = {{"good.png", good}};
    cases.push_back(c);
  };
  add("empty file", "", kRead + ": the file is empty");
  // Offsets: inside the signature; after it; inside IHDR's type, data and CRC; just after IHDR; inside
  // IDAT's header and its data; inside IEND's header; one byte short.
  const std::vector<std::size_t> cuts = {1,        8,         14,       20,       31,      33,
                                         idat + 6, idat + 200, iend - 6, good.size() - 1};
  for (const std::size_t cut : cuts) {
    REQUIRE(cut < good.size());
    add("cut after " + std::to_string(cut) + " of " + std::to_string(good.size()) + " bytes", good.substr(0, cut),
        kRead + (cut < 8 ? ": not a PNG file" : ": the file is truncated"));
  }
  std::string bad_crc = good;
  bad_crc[29] = static_cast<char>(bad_crc[29] ^ 0x5a);
  add("IHDR CRC wrong", bad_crc, kRead + ": IHDR: CRC error");
  std::string bad_data = good;
  for (std::size_t i = idat + 10; i < idat + 30; ++i) bad_data[i] = static_cast<char>(bad_data[i] ^ 0xa5);
  add("IDAT data corrupted (CRC kept wrong)", bad_data, kRead + ": IDAT");
  add("100000 x 100000 in IHDR", with_header(good, 100000, 100000),
      kRead + ": its 100000 x 100000 pixels exceed curvescan's limit");
  add("2^31 - 1 wide in IHDR", with_header(good, 0x7fffffffu, 1), kRead);
  add("zero width in IHDR", with_header(good, 0, 40), kRead + ": Invalid IHDR data");
  add("4000 x 4000 claimed, 48 x 40 of data", with_header(good, 4000, 4000), kRead + ": Not enough image data");
  add("bit depth 3", with_header(good, 48, 40, 3, 6), kRead + ": Invalid IHDR data");
  add("colour type 5", with_header(good, 48, 40, 8, 5), kRead + ": Invalid IHDR data");
  add("an SVG file", R"(<svg xmlns="http://www.w3.org/2000/svg"/>)", kRead + ": not a PNG file");
  add("seeded binary garbage", seeded_garbage(11, 4096), kRead + ": not a PNG file");
  add("the PNG signature then garbage", good.substr(0, 8) + seeded_garbage(12, 1024), kRead);

  BadInputCase directory{"a directory", kArguments, "", 3, "cannot read '[^']*input': it is a directory",
                         InputKind::kDirectory};
  directory.extra_files = {{"good.png", good}};
  cases.push_back(directory);
  BadInputCase missing{"a missing file", kArguments, "", 3, "cannot open '[^']*input' for reading: No such file",
                       InputKind::kMissing};
  missing.extra_files = {{"good.png", good}};
  cases.push_back(missing);
  BadInputCase too_big{"input past --max-input-size", kArguments + " --max-input-size 1",
                       good + std::string(std::size_t{3} << 19, '\0'), 3,
                       "input '[^']*input' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"};
  too_big.extra_files = {{"good.png", good}};
  cases.push_back(too_big);
  // 1 MiB holds three images of 74898 pixels (4 bytes a pixel each, and 2 bytes a pixel to find the
  // difference regions: 2^20 / 14, rounded down); 400 x 400 is refused from its
  // header, before its pixels are allocated (the data behind it is 48 x 40, so a decode would fail later
  // with another message).
  BadInputCase memory{"an image past --max-memory 1", kArguments + " --max-memory 1", with_header(good, 400, 400), 3,
                      "its 400 x 400 pixels exceed .*; the memory limit of 1 MiB allows 74898 pixels an image "
                      "\\(raise --max-memory\\)"};
  memory.extra_files = {{"good.png", good}};
  cases.push_back(memory);
  // Inputs without a size stop at the bound too: a FIFO offering 3 MiB, standard input and /dev/zero,
  // which never ends. A reader without a bound would fail on them with "not a PNG file" instead.
  BadInputCase fifo{"a FIFO offering 3 MiB past --max-input-size 1", kArguments + " --max-input-size 1", "", 3,
                    "input '[^']*input' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)",
                    InputKind::kFifo};
  fifo.extra_files = {{"good.png", good}};
  fifo.fifo_bytes = std::size_t{3} << 20;
  cases.push_back(fifo);
  if (std::filesystem::exists("/dev/zero")) {
    BadInputCase zero{"/dev/zero past --max-input-size 1", "diff {dir}/good.png /dev/zero -o {out} --max-input-size 1",
                      "", 3, "input '/dev/zero' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"};
    zero.extra_files = {{"good.png", good}};
    cases.push_back(zero);
    BadInputCase stdin_zero{"standard input past --max-input-size 1",
                            "diff - {dir}/good.png -o {out} --max-input-size 1 < /dev/zero", "", 3,
                            "input '<stdin>' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"};
    stdin_zero.extra_files = {{"good.png", good}};
    cases.push_back(stdin_zero);
  }
  run_bad_inputs(cases);
}

TEST_CASE("diff: bad outputs and directories are one clear error", "[bad_input][diff]") {
  const std::string good = noise_png();
  std::vector<BadInputCase> cases = {
      {"diff image in a missing directory", "diff {in} {in} -o {dir}/missing/diff.png", good, 3,
       "cannot write '[^']*missing/diff.png'"},
      {"diff image path is a directory", "diff {in} {in} -o {dir}", good, 3, "cannot write"},
      {"directory mode: --expected is missing", "diff --expected {dir}/none --actual {dir} --report {dir}/report",
       good, 3, "--expected '[^']*none' does not exist: give the directory that holds the expected PNG files"},
      {"directory mode: --actual is a file", "diff --expected {dir} --actual {in} --report {dir}/report", good,
       3, "'[^']*input' is not a directory"},
      {"one image only: a usage error", "diff {in} -o {out}", good, 64, "usage error: give two PNG files"},
      {"both images from standard input: a usage error", "diff - - -o {out} < {in}", good, 64,
       "usage error: only one of the two images can come from standard input"},
      {"directory mode without --report: a usage error", "diff --expected {dir} --actual {dir}", good, 64,
       "usage error: directory mode needs"},
  };
  run_bad_inputs(cases);
}

}  // namespace
}  // namespace curvescan::test
