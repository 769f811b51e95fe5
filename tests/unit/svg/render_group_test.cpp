// The render tree's Group node (svg/render_group.h): what group_node resolves for an element -- its
// transform about its transform-origin, opacity, blend mode and isolation, the clip path, mask and filter
// objects it refers to, and its box when those need it -- read from the node as the drawing walk makes it
// (group_node_probe.h), not from pixels.
#include "svg/render_group.h"

#include <catch2/catch.hpp>
#include <map>
#include <string>
#include <vector>

#include "svg/group_node_probe.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::detail;
using curvescan::svg::testing::check_maps;

namespace {

// What a test reads of one Group node, copied while the node lives.
struct SeenGroup {
  Affine transform;
  double opacity = 1.0;
  BlendMode blend_mode = BlendMode::kNormal;
  bool isolate = false;
  std::string clip_path;              // the id of the resolved <clipPath>, "" when none
  const void* clip_object = nullptr;  // which object: the same for every use of one read
  std::string clip_path_unresolved;   // the name of a reference to no <clipPath>
  std::string clip_path_id;           // the id the drawing names in warnings, derived from the node
  std::string mask;                   // the id of the resolved <mask>
  std::string mask_unresolved;
  std::string mask_id;
  std::vector<std::string> filters;  // per entry: the resolved <filter>'s id, "" for a function or none
  std::vector<double> filter_amounts;
  Color current_color;
  std::optional<Rect> box;
};

std::string id_of(const pugi::xml_node& element) {
  return element.attribute("id").value();
}

// The Group nodes of a render of `body` in a 100 x 100 document, by the id of their element, in the order
// made (an element met twice, through <use>, is seen twice).
std::map<std::string, std::vector<SeenGroup>> groups_of(const std::string& body,
                                                        const std::string& root_attributes =
                                                            "width=\"100\" "
                                                            "height=\"100\"") {
  std::map<std::string, std::vector<SeenGroup>> seen;
  const Result<RenderedDocument> rendered =
      render_probing_groups(testing::svg_document(root_attributes, body), RenderOptions{},
                            [&](const pugi::xml_node& element, const GroupNode& group) {
                              SeenGroup copy;
                              copy.transform = group.transform;
                              copy.opacity = group.opacity;
                              copy.blend_mode = group.blend_mode;
                              copy.isolate = group.isolate;
                              if (group.clip_path.resolved)
                                copy.clip_path = id_of(group.clip_path.resolved->element);
                              copy.clip_object = group.clip_path.resolved;
                              copy.clip_path_unresolved = group.clip_path.unresolved;
                              copy.clip_path_id = group.clip_path.id();
                              if (group.mask.resolved) copy.mask = id_of(group.mask.resolved->element);
                              copy.mask_unresolved = group.mask.unresolved;
                              copy.mask_id = group.mask.id();
                              for (const GroupFilter& entry : group.filters) {
                                copy.filters.push_back(entry.filter ? id_of(entry.filter->element) : "");
                                copy.filter_amounts.push_back(entry.function.amount);
                              }
                              copy.current_color = group.current_color;
                              copy.box = group.box;
                              seen[id_of(element)].push_back(copy);
                            });
  REQUIRE(rendered.is_ok());
  return seen;
}

}  // namespace

TEST_CASE("group_node: opacity, blend mode, isolation, clip path, mask and filter resolved into one node",
          "[svg][render_tree][group]") {
  const auto seen = groups_of(
      "<defs><clipPath id=\"c\"><rect width=\"50\" height=\"50\"/></clipPath>"
      "<mask id=\"m\"><rect width=\"100\" height=\"100\" fill=\"white\"/></mask>"
      "<filter id=\"f\"><feOffset dx=\"1\"/></filter></defs>"
      "<g id=\"g\" opacity=\"0.5\" clip-path=\"url(#c)\" mask=\"url(#m)\" filter=\"url(#f)\" color=\"red\" "
      "style=\"mix-blend-mode: multiply; isolation: isolate\">"
      "<rect id=\"r\" x=\"10\" y=\"20\" width=\"30\" height=\"40\"/></g>");
  REQUIRE(seen.count("g") == 1);
  const SeenGroup& g = seen.at("g").front();
  CHECK(g.opacity == 0.5);
  CHECK(g.blend_mode == BlendMode::kMultiply);
  CHECK(g.isolate);
  CHECK(g.clip_path == "c");
  CHECK(g.mask == "m");
  // A resolved reference keeps no name of its own: the id the drawing shows comes from the object.
  CHECK(g.clip_path_unresolved.empty());
  CHECK(g.clip_path_id == "c");
  CHECK(g.mask_unresolved.empty());
  CHECK(g.mask_id == "m");
  CHECK(g.filters == std::vector<std::string>{"f"});
  CHECK(g.current_color == Color{1.0, 0.0, 0.0, 1.0});
  // A mask (maskUnits objectBoundingBox by default) and a filter need the box: the content's.
  REQUIRE(g.box);
  CHECK(*g.box == Rect{10.0, 20.0, 40.0, 60.0});
  CHECK(g.transform == Affine::identity());
  // The rect inside has no effects of its own: its node holds no references and no box.
  const SeenGroup& r = seen.at("r").front();
  CHECK(r.opacity == 1.0);
  CHECK(r.clip_path.empty());
  CHECK(r.clip_path_id.empty());
  CHECK(r.mask_id.empty());
  CHECK(r.mask.empty());
  CHECK(r.filters.empty());
  CHECK_FALSE(r.box);
}

TEST_CASE("group_node: a reference to nothing is kept as its name, with no object",
          "[svg][render_tree][group]") {
  const auto seen = groups_of(
      "<linearGradient id=\"notclip\"/>"
      "<g id=\"g\" clip-path=\"url(#notclip)\" mask=\"url(#missing)\" "
      "style=\"filter: url(#missing) blur(1em); font-size: 10px\"><rect width=\"10\" height=\"10\"/></g>");
  const SeenGroup& g = seen.at("g").front();
  CHECK(g.clip_path.empty());
  CHECK(g.clip_path_unresolved == "notclip");  // the drawing warns "... which is not a <clipPath>"
  CHECK(g.clip_path_id == "notclip");
  CHECK(g.mask.empty());
  CHECK(g.mask_unresolved == "missing");
  CHECK(g.mask_id == "missing");
  CHECK(g.filters == std::vector<std::string>{"", ""});
  // blur(1em): its σ in user units for the element's font size.
  REQUIRE(g.filter_amounts.size() == 2);
  CHECK(g.filter_amounts[1] == 10.0);
}

TEST_CASE("group_node: the transform about its transform-origin", "[svg][render_tree][group]") {
  const auto seen = groups_of(
      "<rect id=\"r\" width=\"10\" height=\"10\" transform=\"rotate(90)\" transform-origin=\"10 20\"/>"
      "<g id=\"g\" transform=\"scale(2)\" style=\"transform-origin: 50% 50%\"><rect width=\"1\" "
      "height=\"1\"/></g>");
  const Affine& rotated = seen.at("r").front().transform;
  check_maps(rotated, {10.0, 20.0}, {10.0, 20.0});  // the origin stays
  check_maps(rotated, {11.0, 20.0}, {10.0, 21.0});  // +x turns to +y about it
  // Percentages of the origin are of the viewport (transform-box: view-box): (50, 50).
  const Affine& scaled = seen.at("g").front().transform;
  check_maps(scaled, {50.0, 50.0}, {50.0, 50.0});
  check_maps(scaled, {60.0, 50.0}, {70.0, 50.0});
  // A shape with no clip path, mask or filter is not measured.
  CHECK_FALSE(seen.at("r").front().box);
}

TEST_CASE("group_node: the root's viewBox mapping follows its transform", "[svg][render_tree][group]") {
  const auto seen = groups_of("<rect width=\"10\" height=\"10\"/>",
                              "id=\"root\" width=\"100\" height=\"100\" viewBox=\"0 0 50 50\" "
                              "transform=\"translate(5 0)\"");
  const Affine& root = seen.at("root").front().transform;
  check_maps(root, {0.0, 0.0}, {5.0, 0.0});
  check_maps(root, {50.0, 50.0}, {105.0, 100.0});
}

TEST_CASE("group_node: through nested <use>, each element's own node, the same objects",
          "[svg][render_tree][group]") {
  const auto seen = groups_of(
      "<defs><clipPath id=\"c\" clipPathUnits=\"objectBoundingBox\"><rect width=\"0.5\" "
      "height=\"1\"/></clipPath>"
      "<g id=\"inner\" opacity=\"0.25\" clip-path=\"url(#c)\"><rect x=\"2\" y=\"4\" width=\"6\" "
      "height=\"8\"/></g>"
      "<use id=\"middle\" href=\"#inner\" x=\"7\" transform=\"translate(10 0)\"/></defs>"
      "<use id=\"outer\" href=\"#middle\" opacity=\"0.5\" transform=\"translate(0 20)\"/>"
      "<use id=\"again\" href=\"#inner\"/>");
  // Each <use> is a group with its own transform (its x and y are the translation of its content, drawn
  // by the walk) and opacity.
  const SeenGroup& outer = seen.at("outer").front();
  check_maps(outer.transform, {0.0, 0.0}, {0.0, 20.0});
  CHECK(outer.opacity == 0.5);
  check_maps(seen.at("middle").front().transform, {0.0, 0.0}, {10.0, 0.0});
  // The referenced <g>, met twice: the same node each time, the clip path read once (the same object),
  // its objectBoundingBox units measured on the group's content.
  REQUIRE(seen.at("inner").size() == 2);
  for (const SeenGroup& inner : seen.at("inner")) {
    CHECK(inner.opacity == 0.25);
    CHECK(inner.clip_path == "c");
    REQUIRE(inner.box);
    CHECK(*inner.box == Rect{2.0, 4.0, 8.0, 12.0});
  }
  CHECK(seen.at("inner")[0].clip_object == seen.at("inner")[1].clip_object);
}

TEST_CASE("group_node: a shape's transform is read before its geometry, even when it has none",
          "[svg][render_tree][group]") {
  // The warnings come in the order the drawing always gave them: the transform's, then the geometry's --
  // and a shape without geometry (a negative width) still has its transform read and reported.
  const RenderedDocument rendered = testing::render(
      testing::svg_document("width=\"20\" height=\"20\"",
                            "<rect width=\"-5\" height=\"5\" transform=\"rotate(bad)\"/>"
                            "<rect width=\"5\" height=\"5\" rx=\"bad\" transform=\"translate(bad)\"/>"));
  const std::vector<std::string>& warnings = rendered.warnings;
  const auto position = [&](const std::string& part) {
    for (std::size_t i = 0; i < warnings.size(); ++i)
      if (warnings[i].find(part) != std::string::npos) return static_cast<int>(i);
    return -1;
  };
  REQUIRE(position("rotate(bad)") >= 0);
  CHECK(position("rotate(bad)") < position("'-5' of property 'width'"));
  CHECK(position("'-5' of property 'width'") < position("translate(bad)"));
  CHECK(position("translate(bad)") < position("'bad' of property 'rx'"));
}
