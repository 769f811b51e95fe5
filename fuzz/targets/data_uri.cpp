// Fuzz target data_uri: the href of an SVG <image> (or <feImage>) as a data: URI (RFC 2397) — the media
// type and its parameters, ";base64" or percent-encoding, white space inside base64 (HTML's forgiving
// decoder), padding, characters outside the alphabet — through decode_data_uri and sniff_image_format
// (raster/svg/image_source.h), and through load_image_source without a base directory, which must refuse
// every other scheme and every file reference without reading anything.
//
// Every document can carry one, and until this target the decoder was reached only through svg_document,
// by the one seed there that holds a data URI. Decoding never makes more bytes than the URI has (base64
// makes 3 of 4, a percent escape 1 of 3, any other character 1): a payload longer than the input is a
// broken decoder, and traps.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "fuzz_targets.h"
#include "svg/image_source.h"

namespace curvescan::fuzz {

int fuzz_data_uri(const std::uint8_t* data, std::size_t size) {
  const std::string_view uri(reinterpret_cast<const char*>(data), size);  // bytes as characters
  const std::optional<std::vector<std::uint8_t>> payload = svg::detail::decode_data_uri(uri);
  if (payload) {
    if (payload->size() > size) __builtin_trap();
    (void)svg::detail::sniff_image_format(*payload);
  }
  // No base directory: what loads is a data URI, decoded to the same payload; anything else is refused.
  const svg::detail::ImageBytes loaded =
      svg::detail::load_image_source(uri, std::nullopt, std::size_t{1} << 16, "the fuzz limit");
  if (loaded.refused.empty() && (!payload || loaded.bytes != *payload)) __builtin_trap();
  return 0;
}

}  // namespace curvescan::fuzz
