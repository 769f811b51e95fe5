// Small helpers shared by the SVG feature tests (masks, patterns, markers, switch, images): a document
// from a body, a render that must succeed, and a message search.
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "curvescan/svg/document.h"

namespace curvescan::svg::testing {

inline std::string svg_document(const std::string& attributes, const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" " +
         attributes + ">" + body + "</svg>";
}

inline RenderedDocument render(const std::string& text, const RenderOptions& options = {}) {
  Result<RenderedDocument> rendered = render_svg_document(text, options);
  INFO(text);
  if (!rendered) INFO(rendered.error().message);
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

inline bool contains(const std::vector<std::string>& messages, const std::string& part) {
  for (const std::string& message : messages) {
    if (message.find(part) != std::string::npos) return true;
  }
  return false;
}

}  // namespace curvescan::svg::testing
