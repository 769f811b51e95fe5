// The font files the font tests read: Debian's fonts-dejavu-core (TrueType outlines) and fonts-cantarell
// (CFF-flavoured OpenType: the file starts with the "OTTO" tag and FreeType reports the format "CFF").
#pragma once

inline constexpr const char* kDejaVuSansFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr const char* kCantarellFile = "/usr/share/fonts/opentype/cantarell/Cantarell-Regular.otf";
