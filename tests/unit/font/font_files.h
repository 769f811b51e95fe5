// The font files the font tests read: Debian's fonts-dejavu-core (TrueType outlines), fonts-cantarell
// (CFF-flavoured OpenType: the file starts with the "OTTO" tag and FreeType reports the format "CFF")
// and fonts-inter-variable (a variable font).
#pragma once

inline constexpr const char* kDejaVuSansFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr const char* kCantarellFile = "/usr/share/fonts/opentype/cantarell/Cantarell-Regular.otf";
// A variable font (OpenType "fvar": axes wght 100..900 and slnt -10..0), Debian's fonts-inter-variable.
inline constexpr const char* kInterVariableFile = "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf";
