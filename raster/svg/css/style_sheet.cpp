// Compiled author style sheets (style_sheet.h).
#include "style_sheet.h"

#include <algorithm>

#include "matching.h"
#include "tokenizer.h"
#include "xml_names.h"

namespace curvescan::svg::css {
namespace {

// At most this many characters of a selector or at-rule are quoted in a warning.
constexpr std::size_t kQuotedLength = 80;

std::string quoted(std::string text) {
  if (text.size() > kQuotedLength) {
    std::size_t cut = kQuotedLength;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
      --cut;  // a whole UTF-8 character
    text = text.substr(0, cut) + "...";
  }
  return "'" + text + "'";
}

// "line L, column C: " of token `index` in the sheet's text (1-based; columns count bytes, as the
// positions of XML errors do).
std::string position_of(const TokenList& tokens, std::size_t index) {
  const std::size_t offset = index < tokens.tokens.size() ? tokens.tokens[index].begin : tokens.source.size();
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < tokens.source.size(); ++i) {
    if (tokens.source[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
}

}  // namespace

void StyleSheets::warn(std::vector<std::string>& warnings, std::string message) {
  if (warnings_ < kMaxStyleWarnings) {
    warnings.push_back(std::move(message));
  } else if (warnings_ == kMaxStyleWarnings) {
    warnings.push_back("further style sheet warnings are not shown");
  }
  ++warnings_;
}

void StyleSheets::add(std::string_view text, std::string_view origin, std::vector<std::string>& warnings,
                      std::string_view media) {
  const std::string where = std::string(origin) + ": ";
  if (text.size() > kMaxStyleSheetBytes - bytes_) {
    warn(warnings, where + "skipped: style sheets of more than " + std::to_string(kMaxStyleSheetBytes) +
                       " bytes in all are not read");
    return;
  }
  bytes_ += text.size();
  const StyleSheetSyntax sheet = parse_style_sheet(text, kMaxStyleSheetTokens);
  if (sheet.tokens.truncated) {
    warn(warnings, where + "more than " + std::to_string(kMaxStyleSheetTokens) +
                       " CSS tokens: the rest of the style sheet is skipped");
  }
  stopped_ = false;
  std::uint32_t sheet_media = 0;
  if (!media.empty()) {  // as an @media block around the whole sheet
    const TokenList media_tokens = tokenize(media);
    std::set<std::string> unsupported;
    Compiled& compiled = writable();
    compiled.media_blocks.push_back(
        MediaBlock{MediaQueryList::parse(media_tokens, 0, media_tokens.tokens.size(), unsupported), 0});
    warn_unsupported_features(unsupported, where, warnings);
    sheet_media = static_cast<std::uint32_t>(compiled.media_blocks.size());
  }
  add_rules(sheet.tokens, sheet.rules, where, sheet_media, 0, warnings);
  set_medium(medium_);
}

void StyleSheets::add_rules(const TokenList& tokens, const std::vector<Rule>& rules, const std::string& origin,
                            std::uint32_t media, int nesting, std::vector<std::string>& warnings) {
  for (const Rule& rule : rules) {
    if (stopped_) return;
    // Each message about a rule says where the rule starts in the sheet's text. Found only for a message
    // that will be shown (at most kMaxStyleWarnings), since it reads the text from its start.
    const auto where = [&] {
      // An at-rule starts at its at-keyword, the token before its prelude.
      const std::size_t start = rule.is_at_rule && rule.prelude_begin > 0 ? rule.prelude_begin - 1 : rule.prelude_begin;
      return warnings_ < kMaxStyleWarnings ? origin + position_of(tokens, start) : origin;
    };
    std::size_t first = rule.prelude_begin, last = rule.prelude_end;
    while (first < last && tokens.tokens[first].type == TokenType::kWhitespace) ++first;
    while (last > first && tokens.tokens[last - 1].type == TokenType::kWhitespace) --last;
    const std::string prelude = serialize_tokens(tokens, first, last);
    if (rule.is_at_rule) {
      if (rule.at_name == "charset") continue;
      if (rule.at_name == "import") {
        warn(warnings, where() + "@import " + quoted(prelude) + " refused: external style sheets are not read");
      } else if (rule.at_name == "media" && rule.has_block &&
                 compiled_->media_blocks.size() >= kMaxMediaBlocks) {
        if (warned_.insert("too many @media").second)
          warn(warnings, where() + "more than " + std::to_string(kMaxMediaBlocks) +
                             " @media blocks in all; the rest are skipped");
      } else if (rule.at_name == "media" && rule.has_block && nesting < kMaxMediaNesting) {
        std::set<std::string> unsupported;
        MediaBlock block{MediaQueryList::parse(tokens, rule.prelude_begin, rule.prelude_end, unsupported),
                         media};
        warn_unsupported_features(unsupported, where(), warnings);
        Compiled& compiled = writable();
        compiled.media_blocks.push_back(std::move(block));
        const auto index = static_cast<std::uint32_t>(compiled.media_blocks.size());
        add_rules(tokens, parse_rule_list(tokens, rule.block_begin, rule.block_end), origin, index,
                  nesting + 1, warnings);
      } else if (rule.at_name == "media" && rule.has_block) {
        warn(warnings,
             where() + "@media nested more than " + std::to_string(kMaxMediaNesting) + " deep is skipped");
      } else if (rule.at_name == "media") {
        warn(warnings, where() + "@media " + quoted(prelude) + " has no {} block; skipped");
      } else if (warned_.insert("@" + rule.at_name).second) {
        warn(warnings, where() + "@" + rule.at_name + " is not supported; the at-rule is skipped");
      }
      continue;
    }
    const Result<std::vector<ComplexSelector>> selectors =
        parse_selector_list(tokens, rule.prelude_begin, rule.prelude_end);
    if (!selectors) {
      warn(warnings, where() + "rule " + quoted(prelude) + " skipped: " + selectors.error().message);
      continue;
    }
    if (selectors->size() > kMaxStyleRules - compiled_->rules.size()) {
      warn(warnings, where() + "more than " + std::to_string(kMaxStyleRules) +
                         " selectors in all; the rest of the style sheet is skipped");
      stopped_ = true;
      return;
    }
    // Every declaration is kept, repeats too: a later one that the property's parser refuses leaves the
    // earlier one in force (`fill: red; fill: 1px`), which only the renderer can tell (cascade.h).
    std::vector<Declaration> declarations = parse_declarations(tokens, rule.block_begin, rule.block_end);
    if (declarations.empty()) continue;
    if (declarations.size() > kMaxStyleDeclarations - declarations_) {
      warn(warnings, where() + "more than " + std::to_string(kMaxStyleDeclarations) +
                         " declarations in all; the rest of the style sheet is skipped");
      stopped_ = true;
      return;
    }
    declarations_ += declarations.size();
    Compiled& compiled = writable();
    compiled.blocks.push_back(std::move(declarations));
    const auto block = static_cast<std::uint32_t>(compiled.blocks.size() - 1);
    for (const ComplexSelector& selector : *selectors) add_rule(selector, block, media);
  }
}

void StyleSheets::warn_unsupported_features(const std::set<std::string>& features, const std::string& where,
                                            std::vector<std::string>& warnings) {
  for (const std::string& feature : features) {
    if (warned_.insert("feature " + feature).second)
      warn(warnings, where + "@media feature '" + feature +
                         "' is not supported; the queries that test it do not match");
  }
}

void StyleSheets::set_medium(const MediaFeatures& medium) {
  medium_ = medium;
  const std::vector<MediaBlock>& blocks = compiled_->media_blocks;
  media_active_.assign(blocks.size(), false);
  // A block's parent comes before it, so one pass in order sees every parent decided.
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const MediaBlock& block = blocks[i];
    const bool parent_active = block.parent == 0 || media_active_[block.parent - 1];
    media_active_[i] = parent_active && block.queries.matches(medium);
  }
}

StyleSheets::Compiled& StyleSheets::writable() {
  if (compiled_.use_count() > 1) compiled_ = std::make_shared<Compiled>(*compiled_);
  return *compiled_;
}

void StyleSheets::add_rule(ComplexSelector selector, std::uint32_t block, std::uint32_t media) {
  Compiled& compiled = writable();
  const auto index = static_cast<std::uint32_t>(compiled.rules.size());
  // The key: the subject compound's id, else a class, else its type; an id narrows the most.
  const std::string* id = nullptr;
  const std::string* class_name = nullptr;
  const std::string* type = nullptr;
  for (const SimpleSelector& simple : selector.compounds.front().simple) {
    if (simple.kind == SimpleSelector::Kind::kId && !id) id = &simple.name;
    if (simple.kind == SimpleSelector::Kind::kClass && !class_name) class_name = &simple.name;
    if (simple.kind == SimpleSelector::Kind::kType && !type) type = &simple.name;
  }
  if (id) {
    compiled.by_id[*id].push_back(index);
  } else if (class_name) {
    compiled.by_class[*class_name].push_back(index);
  } else if (type) {
    compiled.by_type[*type].push_back(index);
  } else {
    compiled.unkeyed.push_back(index);
  }
  compiled.rules.push_back(StyleRule{std::move(selector), block, index, media});
}

void StyleSheets::test(const std::vector<std::uint32_t>& candidates, const pugi::xml_node& element,
                       std::vector<MatchedBlock>& out) const {
  for (const std::uint32_t index : candidates) {
    const StyleRule& rule = compiled_->rules[index];
    if (rule.media != 0 && !media_active_[rule.media - 1]) continue;
    if (matches(rule.selector, element, match_cache_)) {
      out.push_back(MatchedBlock{rule.selector.specificity, rule.order, &compiled_->blocks[rule.block]});
    }
  }
}

void StyleSheets::match(const pugi::xml_node& element, std::vector<MatchedBlock>& out) const {
  out.clear();
  const Compiled& compiled = *compiled_;
  if (compiled.rules.empty()) return;
  const auto lookup = [&](const Index& index, std::string_view key) {
    if (const auto found = index.find(key); found != index.end()) test(found->second, element, out);
  };
  if (const pugi::xml_attribute id = element.attribute("id")) lookup(compiled.by_id, id.value());
  if (!compiled.by_class.empty()) {
    // Each distinct class once: class="a a" must not match a rule twice.
    const std::string_view classes = element.attribute("class").value();
    std::vector<std::string_view> seen;
    std::size_t i = 0;
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; };
    while (i < classes.size()) {
      while (i < classes.size() && space(classes[i])) ++i;
      std::size_t end = i;
      while (end < classes.size() && !space(classes[end])) ++end;
      const std::string_view name = classes.substr(i, end - i);
      if (!name.empty() && std::find(seen.begin(), seen.end(), name) == seen.end()) {
        seen.push_back(name);
        lookup(compiled.by_class, name);
      }
      i = end;
    }
  }
  lookup(compiled.by_type, detail::local_name(element));
  test(compiled.unkeyed, element, out);
  std::sort(out.begin(), out.end(), [](const MatchedBlock& a, const MatchedBlock& b) {
    return a.specificity != b.specificity ? a.specificity < b.specificity : a.order < b.order;
  });
}

}  // namespace curvescan::svg::css
