// Finding an installed font by family name, weight, slant and width through fontconfig, with fallback — what
// CSS/SVG font selection needs (CSS Fonts 3 section 5, "font matching algorithm": the first family of
// the list that is available wins, else the user agent's default).
#pragma once

#include <filesystem>
#include <string>

#include "curvescan/status.h"
#include "curvescan/text/font.h"

namespace curvescan {

/// What to look for.
struct FontQuery {
  /// A CSS font-family list: names separated by commas, optionally quoted ("DejaVu Sans, sans-serif").
  /// Generic families (serif, sans-serif, monospace, cursive, fantasy, system-ui) are fontconfig
  /// aliases and always match.
  std::string family;
  /// CSS / OpenType weight class, 1..1000 (400 regular, 700 bold); clamped into that range.
  int weight = 400;
  bool italic = false;
  /// CSS font-stretch as a percentage of the normal width (50 ultra-condensed .. 200 ultra-expanded),
  /// which is also fontconfig's FC_WIDTH scale (fontconfig-devel, "FC_WIDTH_*" constants).
  double width = 100.0;
};

/// The face fontconfig chose.
struct FontMatch {
  std::filesystem::path file;
  int face_index = 0;
  std::string family;  ///< the chosen face's (first) family name
  std::string style;
  /// True when one of the query's families (or a generic family) was found; false when fontconfig fell
  /// back to its default because none is installed.
  bool family_found = false;
};

/// Asks fontconfig for the best installed face for `query`. kInvalidArgument for an empty family list,
/// kIoError when fontconfig cannot be initialised or knows no font at all.
[[nodiscard]] Result<FontMatch> match_font(const FontQuery& query);

/// match_font, then Font::open on the result. With allow_fallback false, a query none of whose families
/// is installed fails with kInvalidArgument, naming the fallback fontconfig would have used.
[[nodiscard]] Result<Font> load_font(const FontQuery& query, bool allow_fallback);

}  // namespace curvescan
