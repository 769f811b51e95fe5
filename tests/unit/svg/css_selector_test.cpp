// Selector parsing and specificity (svg/css/selector.h; Selectors 3 sections 5, 6 and 9).
#include <catch2/catch.hpp>

#include "svg/css/selector.h"
#include "svg/css/tokenizer.h"

using namespace curvescan;
using namespace curvescan::svg::css;

namespace {

Result<std::vector<ComplexSelector>> parse(std::string_view text, const SelectorLimits& limits = {}) {
  const TokenList list = tokenize(text);
  return parse_selector_list(list, 0, list.tokens.size(), limits);
}

std::uint32_t specificity(std::string_view text) {
  const Result<std::vector<ComplexSelector>> selectors = parse(text);
  INFO(text);
  REQUIRE(selectors.is_ok());
  REQUIRE(selectors->size() == 1);
  return selectors->front().specificity;
}

std::string error_of(std::string_view text) {
  const Result<std::vector<ComplexSelector>> selectors = parse(text);
  INFO(text);
  REQUIRE_FALSE(selectors.is_ok());
  return selectors.error().message;
}

}  // namespace

TEST_CASE("selectors: compounds and combinators are stored right to left") {
  const Result<std::vector<ComplexSelector>> list = parse(" g#g1 > rect.a[x] + *  ~ c d , e ");
  REQUIRE(list.is_ok());
  REQUIRE(list->size() == 2);
  const ComplexSelector& first = list->front();
  REQUIRE(first.compounds.size() == 5);
  CHECK(first.compounds[0].simple.front().name == "d");
  CHECK(first.compounds[4].simple.size() == 2);  // g#g1
  CHECK(first.combinators == std::vector<Combinator>{Combinator::kDescendant, Combinator::kSubsequentSibling,
                                                     Combinator::kNextSibling, Combinator::kChild});
  CHECK(list->back().compounds.size() == 1);
}

TEST_CASE("selectors: specificity (a ids, b classes attributes pseudo-classes, c types — section 9)") {
  CHECK(specificity("*") == pack_specificity(0, 0, 0));
  CHECK(specificity("rect") == pack_specificity(0, 0, 1));
  CHECK(specificity("g rect") == pack_specificity(0, 0, 2));
  CHECK(specificity(".a") == pack_specificity(0, 1, 0));
  CHECK(specificity("[x]") == pack_specificity(0, 1, 0));
  CHECK(specificity("rect:first-child") == pack_specificity(0, 1, 1));
  CHECK(specificity("#a") == pack_specificity(1, 0, 0));
  CHECK(specificity("g#g1 * g * * rect") == pack_specificity(1, 0, 3));
  CHECK(specificity("g#g1 * * rect") == pack_specificity(1, 0, 2));
  // :not() counts as its most specific argument (Selectors 4, 17), the pseudo-class itself nothing.
  CHECK(specificity(":not(#a, .b)") == pack_specificity(1, 0, 0));
  CHECK(specificity("rect:not(.b)") == pack_specificity(0, 1, 1));
  // One id outranks any number of classes.
  CHECK(specificity("#a") > specificity(".a.b.c.d.e.f.g.h.i.j.k"));
}

TEST_CASE("selectors: attribute selectors, quoted or not, with the case flag (6.3)") {
  const Result<std::vector<ComplexSelector>> list =
      parse("[a], [a=b], [a~=\"b c\"], [a|=en], [a^='x'], [a$=y], [a*=z i], [ a = b s ]");
  REQUIRE(list.is_ok());
  REQUIRE(list->size() == 8);
  using Op = AttributeSelector::Operator;
  const std::vector<Op> ops{Op::kExists, Op::kEquals, Op::kIncludes,  Op::kDashMatch,
                            Op::kPrefix, Op::kSuffix, Op::kSubstring, Op::kEquals};
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const AttributeSelector& attribute = (*list)[i].compounds.front().simple.front().attribute;
    CHECK(attribute.name == (i == 0 ? "a" : "a"));
    CHECK(attribute.op == ops[i]);
  }
  CHECK((*list)[2].compounds.front().simple.front().attribute.value == "b c");
  CHECK((*list)[6].compounds.front().simple.front().attribute.ignore_case);
  CHECK_FALSE((*list)[7].compounds.front().simple.front().attribute.ignore_case);
  CHECK(error_of("[a=]").find("malformed") != std::string::npos);
  CHECK(error_of("[a=b c]").find("malformed") != std::string::npos);
  CHECK(error_of("[svg|a]").find("namespaced attribute") != std::string::npos);
}

TEST_CASE("selectors: An+B (CSS Syntax 3 section 6)") {
  using P = std::pair<std::int64_t, std::int64_t>;
  CHECK(parse_an_plus_b("odd") == P{2, 1});
  CHECK(parse_an_plus_b("EVEN") == P{2, 0});
  CHECK(parse_an_plus_b("3") == P{0, 3});
  CHECK(parse_an_plus_b("-n+3") == P{-1, 3});
  CHECK(parse_an_plus_b("2n + 1") == P{2, 1});
  CHECK(parse_an_plus_b("2n-1") == P{2, -1});
  CHECK(parse_an_plus_b("+n") == P{1, 0});
  CHECK(parse_an_plus_b("n") == P{1, 0});
  CHECK_FALSE(parse_an_plus_b("2n1"));
  CHECK_FALSE(parse_an_plus_b("x"));
  CHECK_FALSE(parse_an_plus_b("99999999999n"));  // past the small-integer bound
  const Result<std::vector<ComplexSelector>> list = parse(":nth-child( 2n + 1 )");
  REQUIRE(list.is_ok());
  CHECK(list->front().compounds.front().simple.front().a == 2);
}

TEST_CASE("selectors: unsupported and malformed selectors name what is wrong") {
  CHECK(error_of("a:hover") == "the pseudo-class ':hover' is not supported");
  CHECK(error_of("p::before") == "the pseudo-element '::before' is not supported");
  CHECK(error_of(":lang(en)") == "the pseudo-class ':lang()' is not supported");
  CHECK(error_of("svg|rect") == "the namespace prefix 'svg|' is not supported");
  CHECK(error_of(":not(a b)") == "a combinator inside :not() is not supported");
  CHECK(error_of(":not(:not(a))") == "':not()' inside ':not()' is not supported");
  CHECK(error_of("a,") == "malformed selector: an empty selector");
  CHECK(error_of("a >") == "malformed selector: a combinator at the end");
  CHECK(error_of(".a rect*").find("type selector") != std::string::npos);
  CHECK(error_of("#1a").find("not an identifier") != std::string::npos);
  CHECK(error_of("a { }").find("malformed") != std::string::npos);
}

TEST_CASE("selectors: :is(), :where() and the of-type pseudo-classes (Selectors 4, 4.2, 4.4, 14.4, 17)") {
  // :is() counts as its most specific argument, :where() counts nothing, of-type pseudo-classes as
  // pseudo-classes.
  CHECK(specificity(":is(#a, .b, c)") == pack_specificity(1, 0, 0));
  CHECK(specificity("rect:is(.b, c)") == pack_specificity(0, 1, 1));
  CHECK(specificity(":where(#a, .b) .c") == pack_specificity(0, 1, 0));
  CHECK(specificity("g:where(#a) rect") == pack_specificity(0, 0, 2));
  CHECK(specificity(":not(:is(#a, b))") == pack_specificity(1, 0, 0));
  CHECK(specificity("rect:first-of-type") == pack_specificity(0, 1, 1));
  CHECK(specificity(":nth-last-of-type(2n)") == pack_specificity(0, 1, 0));
  const Result<std::vector<ComplexSelector>> list = parse(":nth-of-type(2n+1)");
  REQUIRE(list.is_ok());
  const SimpleSelector& simple = list->front().compounds.front().simple.front();
  CHECK(simple.kind == SimpleSelector::Kind::kNthOfType);
  CHECK(simple.a == 2);
  CHECK(simple.b == 1);
  // What stays unsupported is named.
  CHECK(error_of(":is(a b)") == "a combinator inside :is() is not supported");
  CHECK(error_of(":where(a > b)") == "a combinator inside :where() is not supported");
  CHECK(error_of(":is()") == "malformed selector: empty argument of :is()");
  CHECK(error_of(":is(a:hover)") == "the pseudo-class ':hover' is not supported");
  CHECK(error_of(":is(:is(:is(:is(:is(a)))))") == "':is()' nested more than 4 deep is not supported");
  CHECK(parse(":is(:is(:is(:is(a))))").is_ok());
  CHECK(error_of(":nth-of-type(x)") == "malformed selector: ':nth-of-type(x)'");
}

TEST_CASE("selectors: the limits on list length, compounds and simple selectors") {
  SelectorLimits limits;
  limits.max_selectors = 2;
  limits.max_compounds = 3;
  limits.max_simple = 2;
  CHECK(parse("a, b", limits).is_ok());
  CHECK(parse("a, b, c", limits).error().kind == curvescan::ErrorKind::kLimitExceeded);
  CHECK(parse("a b c", limits).is_ok());
  CHECK(parse("a b c d", limits).error().kind == curvescan::ErrorKind::kLimitExceeded);
  CHECK(parse("a.b.c", limits).error().kind == curvescan::ErrorKind::kLimitExceeded);
}
