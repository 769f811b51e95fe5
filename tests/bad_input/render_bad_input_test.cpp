// `curvescan render` on bad SVG input: empty, truncated, wrong types, garbage, absurd numbers, deep
// nesting, reference cycles and every render limit. Expected: exit 3 and one line naming the problem
// (or, where SVG prescribes rendering the rest with a warning, exit 0 and that warning), never a crash,
// and no output file after a failure (bad_input_case.h).
#include <random>
#include <string>
#include <vector>

#include "bad_input_case.h"

namespace curvescan::test {
namespace {

const std::string kSvgOpen = R"(<svg xmlns="http://www.w3.org/2000/svg" width="20" height="20">)";

std::string svg(const std::string& body) { return kSvgOpen + body + "</svg>\n"; }

std::string corpus_file(const std::string& name) {
  return read_text(std::string(CURVESCAN_SOURCE_DIR) + "/tests/bad_input/inputs/" + name);
}

// A document with every construct the parser has a state for: declaration, comment, CDATA, entities,
// nested groups, attributes in both quote styles, a gradient and a clip path.
const std::string kRichDocument = R"svg(<?xml version="1.0" encoding="UTF-8"?>
<!-- a comment -->
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="40" height="30">
  <defs>
    <linearGradient id="grad"><stop offset="0" stop-color="red"/><stop offset="1" stop-color='blue'/></linearGradient>
    <clipPath id="clip"><circle cx="20" cy="15" r="12"/></clipPath>
  </defs>
  <style><![CDATA[ rect { fill: green } ]]></style>
  <g clip-path="url(#clip)" opacity="0.5"><rect x="1" y="2" width="30" height="20" fill="url(#grad)"/></g>
  <path d="M 1 1 C 10 30 30 -10 39 29 Z" stroke="black" stroke-dasharray="2 1"/>
  <text x="2" y="20">a &amp; b</text>
</svg>
)svg";

// The document cut right after the first occurrence of `marker` (plus `extra` bytes).
std::string cut_after(const std::string& marker, std::size_t extra = 0) {
  const std::size_t at = kRichDocument.find(marker);
  REQUIRE(at != std::string::npos);
  return kRichDocument.substr(0, at + marker.size() + extra);
}

std::string seeded_garbage(unsigned seed, std::size_t size) {
  std::mt19937 random(seed);
  std::string bytes(size, '\0');
  for (char& c : bytes) c = static_cast<char>(random() & 0xff);
  return bytes;
}

std::string nested_groups(int depth) {
  std::string body;
  body.reserve(static_cast<std::size_t>(depth) * 7 + 64);
  for (int i = 0; i < depth; ++i) body += "<g>";
  body += R"(<rect width="5" height="5"/>)";
  for (int i = 0; i < depth; ++i) body += "</g>";
  return svg(body);
}

// "Billion laughs" of <use>: level k holds ten uses of level k-1, so rendering level 11 is 10^11 elements.
std::string use_laughs() {
  std::string body = R"(<defs><rect id="l0" width="1" height="1"/>)";
  for (int level = 1; level <= 11; ++level) {
    body += "<g id=\"l" + std::to_string(level) + "\">";
    for (int i = 0; i < 10; ++i) body += "<use href=\"#l" + std::to_string(level - 1) + "\"/>";
    body += "</g>";
  }
  return svg(body + R"(</defs><use href="#l11"/>)");
}

// <use> of <use> of ... 40 deep (distinct elements, no cycle).
std::string use_chain(int length) {
  std::string body = R"(<defs><rect id="u0" width="1" height="1"/>)";
  for (int i = 1; i <= length; ++i) {
    body += "<use id=\"u" + std::to_string(i) + "\" href=\"#u" + std::to_string(i - 1) + "\"/>";
  }
  return svg(body + "</defs><use href=\"#u" + std::to_string(length) + "\"/>");
}

// A polygon of `count` seeded random vertices: count mutually crossing edges.
std::string crossing_polygon_element(int count) {
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> coordinate(0.0, 20.0);
  std::string points;
  for (int i = 0; i < count; ++i) {
    points += std::to_string(coordinate(random)) + "," + std::to_string(coordinate(random)) + " ";
  }
  return "<polygon points=\"" + points + "\"/>";
}

std::string crossing_polygon(int count) { return svg(crossing_polygon_element(count)); }

TEST_CASE("the one-line error check takes exactly one error line", "[bad_input]") {
  CHECK(is_one_error_line("curvescan: error: no input\n"));
  CHECK(is_one_error_line("curvescan render: error: " + std::string(100'000, 'x') + "\n"));
  CHECK_FALSE(is_one_error_line("curvescan render: error: no input"));         // no newline
  CHECK_FALSE(is_one_error_line("curvescan render: error: a\nb\n"));           // two lines
  CHECK_FALSE(is_one_error_line("curvescan render: error: \n"));               // no message
  CHECK_FALSE(is_one_error_line("curvescan Render: error: no input\n"));       // not a subcommand
  CHECK_FALSE(is_one_error_line("curvescan render: warning: x\n"));            // not an error
  CHECK_FALSE(is_one_error_line("warning: x\ncurvescan render: error: y\n"));  // something before it
}

TEST_CASE("render: empty, truncated, wrong-type and garbage inputs are one clear error", "[bad_input][render]") {
  const std::string kXml = "not well-formed XML";
  std::vector<BadInputCase> cases = {
      {"empty file", "render {in} -o {out}", "", 3, kXml},
      {"whitespace only", "render {in} -o {out}", "  \n\t\n", 3, kXml},
      {"cut inside the XML declaration", "render {in} -o {out}", cut_after("<?xml ver"), 3, kXml},
      {"cut inside a comment", "render {in} -o {out}", cut_after("<!-- a com"), 3, kXml},
      {"cut mid-tag name", "render {in} -o {out}", cut_after("<linearGr"), 3, kXml},
      {"cut mid-attribute name", "render {in} -o {out}", cut_after("<rect x=\"1\" y=\"2\" wid"), 3, kXml},
      {"cut mid-attribute value", "render {in} -o {out}", cut_after("stop-color='bl"), 3, kXml},
      {"cut after '=' of an attribute", "render {in} -o {out}", cut_after("<circle cx="), 3, kXml},
      {"cut inside CDATA", "render {in} -o {out}", cut_after("<![CDATA[ rect"), 3, kXml},
      {"cut inside an entity", "render {in} -o {out}", cut_after("a &am"), 3, kXml},
      {"cut mid-closing tag", "render {in} -o {out}", cut_after("</sv"), 3, kXml},
      {"cut after the root's start tag", "render {in} -o {out}", cut_after("height=\"30\">"), 3, kXml},
      {"root that is not <svg>", "render {in} -o {out}", "<html><svg/></html>", 3, "not <svg>"},
      {"seeded binary garbage", "render {in} -o {out}", seeded_garbage(8, 4096), 3, kXml},
      {"garbage after a '<'", "render {in} -o {out}", "<" + seeded_garbage(9, 512), 3, kXml},
      {"a PNG file", "render {in} -o {out}", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), 3, kXml},
      {"a directory", "render {in} -o {out}", "", 3, "cannot read '.*': it is a directory", InputKind::kDirectory},
      {"a missing file", "render {in} -o {out}", "", 3, "cannot open '.*' for reading: No such file", InputKind::kMissing},
      {"garbage on standard input", "render - -o {out} < {in}", seeded_garbage(10, 2048), 3, kXml},
  };
  // XML 1.0 section 2.1: one root element, and no text outside it (pugixml alone accepts both).
  cases.push_back({"two root elements", "render {in} -o {out}",
                   svg("<rect width=\"4\" height=\"4\"/>") + svg(""), 3,
                   "not well-formed XML: a second root element <svg> at line 2"});
  cases.push_back({"text before the root element", "render {in} -o {out}", "hello " + svg(""), 3,
                   "not well-formed XML: text before the root element at line 1, column 1"});
  cases.push_back({"text after the root element", "render {in} -o {out}", svg("") + "\nbye\n", 3,
                   "not well-formed XML: text after the root element"});
  // XML 1.0 section 3.1 (Unique Att Spec): pugixml alone accepts a repeated attribute.
  cases.push_back({"an attribute given twice", "render {in} -o {out}",
                   svg("<rect width=\"4\" height=\"4\" width=\"8\"/>"), 3,
                   "not well-formed XML: the attribute 'width' appears twice in <rect>"});
  // Allowed around the root: a declaration, a comment, a processing instruction, a doctype, white space.
  cases.push_back({"comments, a PI and a doctype around the root", "render {in} -o {out}",
                   "<?xml version=\"1.0\"?>\n<!DOCTYPE svg>\n<!-- c -->\n<?pi x?>\n" +
                       svg("<rect width=\"4\" height=\"4\"/>") + "\n<!-- after -->\n",
                   0, "^$"});
  // Inputs without a size stop at the bound: a FIFO offering 3 MiB, and /dev/zero.
  BadInputCase fifo{"a FIFO offering 3 MiB past --max-input-size 1", "render {in} -o {out} --max-input-size 1", "", 3,
                    "input '[^']*input' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)",
                    InputKind::kFifo};
  fifo.fifo_bytes = std::size_t{3} << 20;
  cases.push_back(fifo);
  if (std::filesystem::exists("/dev/zero")) {
    cases.push_back({"/dev/zero past --max-input-size 1", "render /dev/zero -o {out} --max-input-size 1", "", 3,
                     "input '/dev/zero' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"});
  }
  run_bad_inputs(cases);
}

TEST_CASE("render: absurd numbers are refused or ignored as SVG says, never a crash", "[bad_input][render]") {
  const std::string kFar = R"(<path d="M 0 0 L 1e308 1e308 L -1e308 1e308 Z"/>)";
  std::vector<BadInputCase> cases = {
      {"width 1e400 (overflows double): ignored with a warning", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="1e400" height="10"/>)", 0,
       "width: '1e400' is not a length"},
      {"width NaN: ignored with a warning", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="NaN" height="10"/>)", 0,
       "width: 'NaN' is not a length"},
      // A side beyond 32767 pixels: --max-pixels cannot help, and the message does not say it would.
      {"width 1e9: the side limit", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="1e9" height="10"/>)", 3,
       "1000000000 x 10 pixels \\(the document's size 1e\\+09 x 10 px\\), beyond the limit of 32767 pixels "
       "per side: give a smaller -w, -h or -z"},
      {"width 1e308: the side limit, the size in exponent form (not its first 63 of 309 digits)",
       "render {in} -o {out}", R"(<svg xmlns="http://www.w3.org/2000/svg" width="1e308" height="1e308"/>)", 3,
       "the output would be 1e\\+308 x 1e\\+308 pixels \\(the document's size 1e\\+308 x 1e\\+308 px\\), "
       "beyond "
       "the limit of 32767 pixels per side"},
      {"the pixel limit: --max-pixels can reach it", "render {in} -o {out} -w 5000 --max-pixels 16777216",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100"/>)", 3,
       "the output would be 5000 x 5000 pixels \\(the document's size 100 x 100 px, -w 5000 px\\), "
       "25000000 in all, beyond the limit of 16777216 pixels \\(raise it with --max-pixels, up to 67108864, "
       "or give a smaller -w, -h or -z\\)"},
      // -w 1e308 on a document twice as tall: the height overflows a double, and is still a number.
      {"-w 1e308: the given width and a finite height", "render {in} -o {out} -w 1e308",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="200"/>)", 3,
       "the output would be 1e\\+308 x 2e\\+308 pixels \\(the document's size 100 x 200 px, -w 1e\\+308 "
       "px\\), "
       "beyond the limit of 32767 pixels per side: give a smaller -w, -h or -z"},
      {"-h 1e308 -a with -w 1: within the limits", "render {in} -o {out} -w 1 -h 1e308 -a",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="200"/>)", 0, "^$"},
      {"--dpi 1e6 on a document in inches: the resolution named", "render {in} -o {out} --dpi 1e6",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="100in" height="200in"/>)", 3,
       "the output would be 100000000 x 200000000 pixels \\(the document's size 1e\\+08 x 2e\\+08 px at "
       "--dpi "
       "1e\\+06\\), beyond the limit of 32767 pixels per side"},
      {"--page-width 1e308", "render {in} -o {out} --page-width 1e308 --page-height 1", svg(""), 3,
       "1e\\+308 x 1 pixels \\(the document's size 20 x 20 px, --page-width 1e\\+308 px, --page-height 1 "
       "px\\), "
       "beyond the limit of 32767 pixels per side: give a smaller --page-width and --page-height"},
      {"-w 1e-10: under one pixel, a larger size asked for", "render {in} -o {out} -w 1e-10", svg(""), 3,
       "the output would be 0 x 0 pixels \\(the document's size 20 x 20 px, -w 1e-10 px\\): an image is at "
       "least "
       "1 pixel wide and tall; give a larger -w, -h or -z"},
      // A 1e300 px document zoomed 1e9 times, capped by -w/-h: 1e309 overflowed, and 100 / inf * inf was NaN.
      {"-z 1e9 capped by -w 10 -h 10 -a on a 1e300 document", "render {in} -o {out} -z 1e9 -w 10 -h 10 -a",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="1e300" height="1e300"/>)", 0, "^$"},
      {"zoom 1e9 on a 1e9 document: 1e18 pixels", "render {in} -o {out} -z 1e9",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="1e9" height="1e9"/>)", 3,
       "1e\\+18 x 1e\\+18 pixels \\(the document's size 1e\\+09 x 1e\\+09 px, -z 1e\\+09\\), beyond the "
       "limit of 32767 pixels per side"},
      {"width -0", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="-0" height="10"/>)", 3,
       "no positive width and height"},
      {"negative height", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="10" height="-10"/>)", 3,
       "no positive width and height"},
      {"viewBox 0 0 0 0 and no size", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 0 0"/>)", 3, "no positive width and height"},
      {"viewBox 0 0 0 0 with a size: rendering disabled (SVG 1.1 7.7)", "render {in} -o {out}",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10" viewBox="0 0 0 0"><rect width="5" height="5"/></svg>)",
       0, "^$"},
      {"shape sizes NaN, 1e400 and negative: ignored with warnings", "render {in} -o {out}",
       svg(R"(<rect width="NaN" height="1e400"/><circle r="-5"/><ellipse rx="1e308" ry="-0"/>)"), 0,
       "'width': 'NaN' is not a length"},
      {"path coordinates near the double limit", "render {in} -o {out}", svg(kFar), 0, "^$|warning"},
      {"path coordinates beyond double", "render {in} -o {out}",
       svg(R"(<path d="M 0 0 L 1e400 5 L 5 5 Z"/>)"), 0, "path"},
      {"transform with NaN and 1e308 scale", "render {in} -o {out}",
       svg(R"svg(<g transform="scale(1e308) translate(NaN)"><rect width="5" height="5"/></g><rect transform="matrix(1e308 0 0 1e308 0 0)" width="5" height="5"/>)svg"),
       0, "^$|warning"},
      {"stroke-width 1e308 and a NaN dash array", "render {in} -o {out}",
       svg(R"(<path d="M1 1 L 9 9" stroke="black" stroke-width="1e308" stroke-dasharray="NaN 1"/>)"), 0,
       "^$|warning"},
      // Bytes of an undeclared encoding in <text>: where, what, and what to do.
      {"Latin-1 bytes in <text> of a document without an encoding declaration", "render {in} -o {out}",
       svg("<text y=\"10\">caf\xE9</text>"), 0,
       "input: line 1, column [0-9]+: the character data of a <text> is not valid UTF-8: byte 0xE9 at offset "
       "3 \\(the 4th byte\\) "
       "starts a character that the text ends before completing; skipped \\(save the document as UTF-8, or "
       "name "
       "its encoding in the XML declaration"},
      {"-w 1e400 on the command line", "render {in} -o {out} -w 1e400", svg(""), 64, "usage error"},
      {"-z NaN on the command line", "render {in} -o {out} -z nan", svg(""), 64, "usage error"},
      {"-h -0 on the command line", "render {in} -o {out} -h -0", svg(""), 64, "usage error"},
  };
  run_bad_inputs(cases);
}

TEST_CASE("render: deep nesting and reference cycles end with a limit or a warning", "[bad_input][render]") {
  std::vector<BadInputCase> cases = {
      {"10^5 nested <g>", "render {in} -o {out}", nested_groups(100'000), 3,
       "nested more than 256 deep \\(raise --max-depth\\)"},
      {"10^5 nested <g> with the largest --max-depth: no stack overflow", "render {in} -o {out} --max-depth 4096",
       nested_groups(100'000), 3, "nested more than 4096 deep \\(raise --max-depth\\)"},
      {"--max-depth beyond what the render stack is sized for", "render {in} -o {out} --max-depth 100000",
       nested_groups(10), 64, "--max-depth"},
      {"<use> cycles (SVG 1.1 5.6)", "render {in} -o {out}", corpus_file("use_cycle.svg"), 0,
       "<use> of '#b' is circular; skipped"},
      {"gradient href cycles", "render {in} -o {out}", corpus_file("gradient_href_cycle.svg"), 0,
       "gradient href '#a' is circular"},
      {"clip-path referring to itself", "render {in} -o {out}", corpus_file("clip_path_self.svg"), 0, "^$|warning"},
      {"DTD entity expansion bomb", "render {in} -o {out}", corpus_file("entity_bomb.svg"), 3,
       "entity expansion exceeds 8388608 bytes"},
      {"billion laughs of <use>", "render {in} -o {out} --max-elements 10000", use_laughs(), 3,
       "more than 10000 elements, <use> expansions included \\(raise --max-elements\\)"},
      // At the default limit too: counted before drawing (the document index), so refused at once.
      {"billion laughs of <use>, default limit", "render {in} -o {out}", use_laughs(), 3,
       "more than 1000000 elements, <use> expansions included \\(raise --max-elements\\)"},
      {"<use> chain 40 deep", "render {in} -o {out}", use_chain(40), 3,
       "<use> elements are nested more than 32 deep \\(raise --max-use-depth\\)"},
      {"<use> chain 40 deep, raised use depth", "render {in} -o {out} --max-use-depth 64", use_chain(40), 0, "^$"},
  };
  run_bad_inputs(cases);
}

TEST_CASE("render: every render limit is one line naming the limit, its value and the flag", "[bad_input][render][limits]") {
  std::string big_document = svg("<!--" + std::string((std::size_t{3} << 19), 'x') + "-->");  // 1.5 MiB
  std::vector<BadInputCase> cases = {
      // Squeezed onto the canvas by the transform: all 10^7 dashes can be seen (dashes that cannot are not
      // made, and not counted).
      {"10^7 dashes from a tiny dash period", "render {in} -o {out}",
       svg(R"svg(<path transform="scale(0.001 1)" d="M 0 5 L 100000 5" stroke="black" stroke-dasharray="0.005 0.005"/>)svg"),
       3, "more than 1048576 dashes, the dash limit per stroke \\(raise --max-dashes\\)"},
      {"dashes under a lowered --max-dashes", "render {in} -o {out} --max-dashes 100",
       svg(R"(<path d="M 0 5 L 20 5" stroke="black" stroke-dasharray="0.1"/>)"), 3,
       "more than 100 dashes.*--max-dashes"},
      {"crossing segments past --max-segments", "render {in} -o {out} --max-segments 1000",
       crossing_polygon(5000), 3,
       "flattens to more than 1000 line segments, the segment limit per render \\(raise --max-segments\\)"},
      {"segments counted over the whole render", "render {in} -o {out} --max-segments 100", svg([] {
         std::string shapes;
         for (int i = 0; i < 40; ++i) shapes += R"(<rect width="5" height="5"/>)";
         return shapes;
       }()),
       3, "more than 100 line segments"},
      {"a clip path past --max-segments", "render {in} -o {out} --max-segments 1000",
       svg("<clipPath id=\"c\">" + crossing_polygon_element(5000) +
           "</clipPath><rect width=\"5\" height=\"5\" clip-path=\"url(#c)\"/>"),
       3, "more than 1000 line segments"},
      {"canvas past --max-memory", "render {in} -o {out} --max-memory 1",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="1000" height="1000"/>)", 3,
       "a 1000 x 1000 canvas needs 4 MiB, beyond the memory limit of 1 MiB per render \\(raise "
       "--max-memory\\)"},
      {"opacity layers past --max-memory", "render {in} -o {out} --max-memory 10",
       R"(<svg xmlns="http://www.w3.org/2000/svg" width="1000" height="1000"><g opacity="0.5"><g opacity="0.5"><rect width="5" height="5"/></g></g></svg>)",
       // The canvas and two layers of 4,000,000 bytes each, and the XML tree: 12 MiB; 13 MiB on Linux, where
       // each 4 MB image takes two whole huge pages (zeroed_memory.h) and is counted so.
       3,
       "an opacity layer needs 1[23] MiB, beyond the memory limit of 10 MiB per render \\(raise "
       "--max-memory\\)"},
      {"clip masks past --max-memory", "render {in} -o {out} --max-memory 5",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="1000" height="1000"><clipPath id="c"><rect width="9" height="9"/></clipPath><g clip-path="url(#c)"><g clip-path="url(#c)"><rect width="5" height="5"/></g></g></svg>)svg",
       3, "a clip mask needs 6 MiB, beyond the memory limit of 5 MiB.*--max-memory"},
      {"edges past --max-memory", "render {in} -o {out} --max-memory 1", crossing_polygon(20000), 3,
       "a fill of more than [0-9]+ edges needs 2 MiB, beyond the memory limit of 1 MiB.*--max-memory"},
      {"input past --max-input-size", "render {in} -o {out} --max-input-size 1", big_document, 3,
       "larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"},
      {"input past --max-input-size on standard input", "render - -o {out} --max-input-size 1 < {in}",
       big_document, 3, "input '<stdin>' is larger than the input size limit of 1 MiB"},
      {"canvas past --max-pixels", "render {in} -o {out} --max-pixels 100", svg(""), 3,
       "20 x 20 pixels \\(the document's size 20 x 20 px\\), 400 in all, beyond the limit of 100 pixels "
       "\\(raise it with --max-pixels"},
  };
  run_bad_inputs(cases);
}

TEST_CASE("render: an output path that cannot be written is an error, nothing written", "[bad_input][render]") {
  std::vector<BadInputCase> cases = {
      {"output in a missing directory", "render {in} -o {dir}/missing/out.png", svg(""), 3, "cannot write"},
      {"output path is a directory", "render {in} -o {dir}", svg(""), 3, "cannot write"},
  };
  run_bad_inputs(cases);
}

}  // namespace
}  // namespace curvescan::test
