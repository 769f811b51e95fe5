// Selector matching against an XML tree (svg/css/matching.h; Selectors 3 sections 6 and 8), one
// TEST_CASE per kind of selector.
#include <catch2/catch.hpp>
#include <functional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "svg/css/matching.h"
#include "svg/css/tokenizer.h"

using namespace curvescan;
using namespace curvescan::svg::css;

namespace {

// Children of g1: r1 (first), c1, r2, r3 (last); g2 nested in g1's parent.
constexpr const char* kTree = R"(<svg xmlns="http://www.w3.org/2000/svg" id="root">
  <g id="g1" class="outer  group" lang="en-US">
    <rect id="r1" class="a b" x="1" data-name="Hello World"/>
    <circle id="c1" class="b"/>
    <rect id="r2" x="" />
    <svg:rect xmlns:svg="http://www.w3.org/2000/svg" id="r3" class="a"/>
  </g>
  <g id="g2"><g id="g3"><path id="p1"/></g></g>
  <g id="empty"></g>
</svg>)";

class Tree {
 public:
  Tree() { REQUIRE(document_.load_string(kTree)); }

  // Whether `selector` (a single complex selector) selects the element with id `id`.
  bool selects(std::string_view selector, const char* id) const {
    const TokenList list = tokenize(selector);
    const Result<std::vector<ComplexSelector>> parsed = parse_selector_list(list, 0, list.tokens.size());
    INFO(selector);
    REQUIRE(parsed.is_ok());
    REQUIRE(parsed->size() == 1);
    const pugi::xml_node element = document_.find_node(
        [&](const pugi::xml_node& node) { return std::string_view(node.attribute("id").value()) == id; });
    REQUIRE(element);
    return matches(parsed->front(), element, cache_);
  }

 private:
  pugi::xml_document document_;
  MatchCache cache_;
};

}  // namespace

TEST_CASE("matching: type and universal selectors — prefixed names compare by local name") {
  const Tree tree;
  CHECK(tree.selects("rect", "r1"));
  CHECK_FALSE(tree.selects("rect", "c1"));
  CHECK_FALSE(tree.selects("RECT", "r1"));  // XML names are case-sensitive
  CHECK(tree.selects("rect", "r3"));        // <svg:rect>
  CHECK(tree.selects("*", "c1"));
  CHECK(tree.selects("*", "root"));
}

TEST_CASE("matching: class and id selectors") {
  const Tree tree;
  CHECK(tree.selects(".a", "r1"));
  CHECK(tree.selects(".a.b", "r1"));
  CHECK_FALSE(tree.selects(".a.b", "r3"));
  CHECK(tree.selects(".group", "g1"));  // any word of a whitespace-separated class list
  CHECK_FALSE(tree.selects(".grou", "g1"));
  CHECK(tree.selects("#c1", "c1"));
  CHECK(tree.selects("circle#c1.b", "c1"));
  CHECK_FALSE(tree.selects("#C1", "c1"));
}

TEST_CASE("matching: attribute selectors, every operator (6.3.1, 6.3.2)") {
  const Tree tree;
  CHECK(tree.selects("[x]", "r1"));
  CHECK(tree.selects("[x]", "r2"));  // present though empty
  CHECK_FALSE(tree.selects("[x]", "c1"));
  CHECK(tree.selects("[x='1']", "r1"));
  CHECK(tree.selects("[x=\"\"]", "r2"));
  CHECK(tree.selects("[data-name~=World]", "r1"));
  CHECK_FALSE(tree.selects("[data-name~='Hello World']", "r1"));  // a word never holds whitespace
  CHECK(tree.selects("[lang|=en]", "g1"));
  CHECK_FALSE(tree.selects("[lang|=en-U]", "g1"));
  CHECK(tree.selects("[data-name^=Hell]", "r1"));
  CHECK(tree.selects("[data-name$=rld]", "r1"));
  CHECK(tree.selects("[data-name*='o W']", "r1"));
  CHECK_FALSE(tree.selects("[x^='']", "r2"));  // an empty value matches nothing with ^= $= *=
  CHECK_FALSE(tree.selects("[data-name*=world]", "r1"));
  CHECK(tree.selects("[data-name*=world i]", "r1"));
}

TEST_CASE("matching: descendant and child combinators, with backtracking") {
  const Tree tree;
  CHECK(tree.selects("svg rect", "r1"));
  CHECK(tree.selects("svg > g > rect", "r1"));
  CHECK_FALSE(tree.selects("svg > rect", "r1"));
  CHECK(tree.selects("g path", "p1"));
  CHECK(tree.selects("#g2 > g > path", "p1"));
  CHECK(tree.selects("#g2 path", "p1"));
  CHECK_FALSE(tree.selects("#g1 path", "p1"));
  // "g > g path": the nearest g ancestor (g3) has a g parent; so does it through backtracking.
  CHECK(tree.selects("svg > g > g > path", "p1"));
  CHECK(tree.selects("g > g path", "p1"));
  CHECK_FALSE(tree.selects("g > g > g path", "p1"));
}

TEST_CASE("matching: next-sibling and subsequent-sibling combinators") {
  const Tree tree;
  CHECK(tree.selects("rect + circle", "c1"));
  CHECK(tree.selects("circle + rect", "r2"));
  CHECK_FALSE(tree.selects("rect + rect", "r2"));
  CHECK(tree.selects("#r1 ~ rect", "r3"));
  CHECK_FALSE(tree.selects("#r3 ~ rect", "r1"));
  CHECK(tree.selects("#g1 > .a ~ circle", "c1"));
  // '~' then a descendant combinator: the sibling must be found under some g
  CHECK(tree.selects("g circle ~ rect", "r2"));
  CHECK_FALSE(tree.selects("#g2 circle ~ rect", "r2"));
}

TEST_CASE("matching: :first-child, :last-child, :only-child, :nth-child, :nth-last-child") {
  const Tree tree;
  CHECK(tree.selects("rect:first-child", "r1"));
  CHECK_FALSE(tree.selects(":first-child", "c1"));
  CHECK(tree.selects(":last-child", "r3"));
  CHECK(tree.selects(":only-child", "g3"));
  CHECK_FALSE(tree.selects(":only-child", "r1"));
  CHECK(tree.selects(":nth-child(2)", "c1"));
  CHECK(tree.selects(":nth-child(odd)", "r2"));
  CHECK(tree.selects(":nth-child(even)", "r3"));
  CHECK_FALSE(tree.selects(":nth-child(even)", "r1"));
  CHECK(tree.selects(":nth-child(-n+2)", "c1"));
  CHECK_FALSE(tree.selects(":nth-child(-n+2)", "r2"));
  CHECK(tree.selects(":nth-child(3n)", "r2"));
  CHECK(tree.selects(":nth-last-child(2)", "r2"));
}

TEST_CASE("matching: :first-of-type, :last-of-type, :only-of-type, :nth-of-type, :nth-last-of-type") {
  // g1's children by type: rect r1, r2, r3 (the prefixed <svg:rect> is a rect: local names, as type
  // selectors compare) and circle c1 (Selectors 4, 14.4.5 to 14.4.10).
  const Tree tree;
  CHECK(tree.selects("rect:first-of-type", "r1"));
  CHECK(tree.selects(":first-of-type", "c1"));  // the first circle, though the second child
  CHECK_FALSE(tree.selects(":first-of-type", "r2"));
  CHECK(tree.selects(":last-of-type", "r3"));
  CHECK(tree.selects(":last-of-type", "c1"));
  CHECK_FALSE(tree.selects(":last-of-type", "r2"));
  CHECK(tree.selects(":only-of-type", "c1"));
  CHECK_FALSE(tree.selects(":only-of-type", "r1"));
  CHECK(tree.selects(":only-of-type", "p1"));
  CHECK(tree.selects(":nth-of-type(2)", "r2"));
  CHECK(tree.selects(":nth-of-type(odd)", "r3"));
  CHECK_FALSE(tree.selects(":nth-of-type(even)", "c1"));
  CHECK(tree.selects(":nth-last-of-type(3)", "r1"));
  CHECK(tree.selects(":nth-last-of-type(-n+2)", "r2"));
  CHECK_FALSE(tree.selects(":nth-last-of-type(-n+2)", "r1"));
  // Among g2, g3's parent and the root's <g> children: g1, g2 and empty are the root's three <g>.
  CHECK(tree.selects("g:nth-of-type(2)", "g2"));
  CHECK(tree.selects("g:last-of-type", "empty"));
}

TEST_CASE("matching: :is() and :where() match what one of their arguments matches") {
  const Tree tree;
  CHECK(tree.selects(":is(circle, .a)", "r1"));
  CHECK(tree.selects(":is(circle, .a)", "c1"));
  CHECK_FALSE(tree.selects(":is(circle, .a)", "r2"));
  CHECK(tree.selects(":where(#r2, #nothing)", "r2"));
  CHECK(tree.selects("g :is(rect, circle):not(.a)", "r2"));
  CHECK(tree.selects(":is(g) > :where(rect:first-of-type)", "r1"));
  CHECK_FALSE(tree.selects(":is(g) > :where(rect:first-of-type)", "r2"));
  CHECK(tree.selects(":not(:is(rect, circle))", "g1"));  // :is() inside :not()
  CHECK_FALSE(tree.selects(":not(:is(rect, circle))", "c1"));
}

TEST_CASE("matching: :not(), :root and :empty") {
  const Tree tree;
  CHECK(tree.selects("rect:not(.a)", "r2"));
  CHECK_FALSE(tree.selects("rect:not(.a)", "r1"));
  CHECK_FALSE(tree.selects(":not(circle, [x])", "r1"));
  CHECK(tree.selects(":not(circle, [x])", "r3"));
  CHECK(tree.selects(":root", "root"));
  CHECK_FALSE(tree.selects(":root", "g1"));
  CHECK(tree.selects(":root > g", "g2"));
  CHECK(tree.selects(":empty", "empty"));
  CHECK(tree.selects(":empty", "p1"));
  CHECK_FALSE(tree.selects(":empty", "g1"));
}

TEST_CASE("matching: a long descendant chain on a deep tree stays fast (no exponential backtracking)") {
  // 200 nested <g> and a selector of 30 'g' compounds that fails only at its leftmost part: without the
  // global-failure cut this backtracks through C(200, 30) ancestor choices.
  std::string xml = "<svg xmlns='http://www.w3.org/2000/svg'>";
  for (int i = 0; i < 200; ++i) xml += "<g>";
  xml += "<path id='leaf'/>";
  for (int i = 0; i < 200; ++i) xml += "</g>";
  xml += "</svg>";
  pugi::xml_document document;
  REQUIRE(document.load_string(xml.c_str()));
  std::string selector = "circle";
  for (int i = 0; i < 30; ++i) selector += " g";
  selector += " path";
  const TokenList list = tokenize(selector);
  const Result<std::vector<ComplexSelector>> parsed = parse_selector_list(list, 0, list.tokens.size());
  REQUIRE(parsed.is_ok());
  const pugi::xml_node leaf = document.find_node([](const pugi::xml_node& n) { return n.attribute("id"); });
  CHECK_FALSE(matches(parsed->front(), leaf, MatchCache{}));
}

TEST_CASE("matching: long sibling lists — positions and '~' looked up agree with a direct count") {
  // 300 siblings with pseudo-random classes a/b/c, in a <g class="p"> and in a <g>; the cache answers
  // `~` from the 33rd sibling on and numbers positions per parent (matching.h). The oracle below counts
  // and scans the siblings directly, so every element is checked against an independent answer.
  std::uint32_t state = 12345;
  const auto next = [&] { return state = state * 1103515245u + 12345u, (state >> 16) % 7; };
  std::vector<std::vector<std::string>> classes(2);
  std::string xml = "<svg xmlns='http://www.w3.org/2000/svg'>";
  for (int group = 0; group < 2; ++group) {
    xml += group == 0 ? "<g class='p'>" : "<g>";
    for (int i = 0; i < 300; ++i) {
      const std::uint32_t r = next();
      const std::string name = r < 1 ? "a" : r < 3 ? "b" : r < 5 ? "c" : "";
      classes[group].push_back(name);
      xml += "<rect class='" + name + "'/>";
      if (i % 50 == 0) xml += "<!-- not an element -->text";
    }
    xml += "</g>";
  }
  xml += "</svg>";
  pugi::xml_document document;
  REQUIRE(document.load_string(xml.c_str()));
  const auto has = [](const std::vector<std::string>& list, std::size_t i, const char* name) {
    return list[i] == name;
  };
  // Whether some j < i has class `name` (and, when `before` is given, some k < j has class `before`).
  const auto earlier = [&](const std::vector<std::string>& list, std::size_t i, const char* name,
                           const char* before) {
    for (std::size_t j = 0; j < i; ++j) {
      if (!has(list, j, name)) continue;
      if (!before) return true;
      for (std::size_t k = 0; k < j; ++k) {
        if (has(list, k, before)) return true;
      }
    }
    return false;
  };
  struct Case {
    const char* selector;
    std::function<bool(int group, std::size_t i)> oracle;
  };
  const std::vector<std::string>* lists = classes.data();
  const Case cases[] = {
      {".a ~ .b",
       [&](int g, std::size_t i) { return has(lists[g], i, "b") && earlier(lists[g], i, "a", nullptr); }},
      {".a ~ .b ~ .c",
       [&](int g, std::size_t i) { return has(lists[g], i, "c") && earlier(lists[g], i, "b", "a"); }},
      {".p .c ~ rect", [&](int g, std::size_t i) { return g == 0 && earlier(lists[g], i, "c", nullptr); }},
      {".p > .a ~ .a",
       [&](int g, std::size_t i) {
         return g == 0 && has(lists[g], i, "a") && earlier(lists[g], i, "a", nullptr);
       }},
      {":nth-child(7n+3)", [&](int, std::size_t i) { return (i + 1) % 7 == 3; }},
      {":nth-last-child(2)", [&](int, std::size_t i) { return i == 298; }},
      {"rect:last-child", [&](int, std::size_t i) { return i == 299; }},
      {":nth-child(5) ~ .a", [&](int g, std::size_t i) { return i > 4 && has(lists[g], i, "a"); }},
  };
  for (const Case& test : cases) {
    const TokenList list = tokenize(test.selector);
    const Result<std::vector<ComplexSelector>> parsed = parse_selector_list(list, 0, list.tokens.size());
    REQUIRE(parsed.is_ok());
    const MatchCache cache;  // one per selector: answers must not depend on what was asked before
    int group = 0;
    for (pugi::xml_node g = document.document_element().first_child(); g; g = g.next_sibling(), ++group) {
      std::size_t i = 0;
      for (pugi::xml_node rect = g.first_child(); rect; rect = rect.next_sibling()) {
        if (rect.type() != pugi::node_element) continue;
        INFO(test.selector << " group " << group << " element " << i);
        CHECK(matches(parsed->front(), rect, cache) == test.oracle(group, i));
        ++i;
      }
    }
  }
}
