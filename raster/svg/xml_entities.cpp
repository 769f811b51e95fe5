// Internal DTD entities (xml_entities.h). Section numbers refer to XML 1.0 (fifth edition).
#include "xml_entities.h"

#include <algorithm>
#include <cstdint>
#include <set>
#include <unordered_map>

#include "curvescan/text/utf8.h"

namespace curvescan::svg::detail {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}
// 2.3 NameStartChar / NameChar, with every non-ASCII byte accepted (the XML parser checks names later).
bool is_name_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
         static_cast<unsigned char>(c) >= 0x80;
}
bool is_name_char(char c) {
  return is_name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

// "&#N;" or "&#xN;" at the start of `text`: the code point and the length, or nullopt.
std::optional<std::pair<std::uint32_t, std::size_t>> character_reference(std::string_view text) {
  if (text.size() < 4 || text[0] != '&' || text[1] != '#') return std::nullopt;
  const bool hex = text[2] == 'x';
  std::size_t i = hex ? 3 : 2;
  std::uint32_t value = 0;
  const std::size_t digits_start = i;
  for (; i < text.size() && text[i] != ';'; ++i) {
    const char c = text[i];
    int digit;
    if (c >= '0' && c <= '9') {
      digit = c - '0';
    } else if (hex && (c | 0x20) >= 'a' && (c | 0x20) <= 'f') {
      digit = (c | 0x20) - 'a' + 10;
    } else {
      return std::nullopt;
    }
    value = value * (hex ? 16 : 10) + static_cast<std::uint32_t>(digit);
    if (value > 0x10FFFF) return std::nullopt;
  }
  if (i == digits_start || i >= text.size() || value == 0) return std::nullopt;
  return std::pair{value, i + 1};
}

// "&name;" at the start of `text`: the name, or empty.
std::string_view entity_reference(std::string_view text) {
  if (text.size() < 3 || text[0] != '&' || !is_name_start(text[1])) return {};
  std::size_t i = 2;
  while (i < text.size() && is_name_char(text[i])) ++i;
  if (i >= text.size() || text[i] != ';') return {};
  return text.substr(1, i - 1);
}

bool is_predefined(std::string_view name) {
  return name == "lt" || name == "gt" || name == "amp" || name == "apos" || name == "quot";
}

struct Entity {
  bool external = false;
  std::string replacement;  // internal entities: the value with character references replaced
};

// The end of a quoted literal starting at `i` (the quote), or npos.
std::size_t literal_end(std::string_view text, std::size_t i) {
  const std::size_t close = text.find(text[i], i + 1);
  return close == std::string_view::npos ? close : close + 1;
}

// The end of the markup declaration starting at `i` ("<!..."): just after its '>', skipping literals.
std::size_t declaration_end(std::string_view text, std::size_t i) {
  if (text.substr(i, 4) == "<!--") {
    const std::size_t close = text.find("-->", i + 4);
    return close == std::string_view::npos ? close : close + 3;
  }
  for (; i < text.size(); ++i) {
    if (text[i] == '"' || text[i] == '\'') {
      i = literal_end(text, i);
      if (i == std::string_view::npos) return i;
      --i;
    } else if (text[i] == '>') {
      return i + 1;
    }
  }
  return std::string_view::npos;
}

// The end of the comment, CDATA section or processing instruction starting at `i`, or npos when none
// starts there. These are copied verbatim (an unterminated one runs to the end).
std::size_t verbatim_end(std::string_view text, std::size_t i) {
  for (const auto& [open, close] :
       {std::pair<std::string_view, std::string_view>{"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}}) {
    if (text.substr(i, open.size()) == open) {
      const std::size_t end = text.find(close, i + open.size());
      return end == std::string_view::npos ? text.size() : end + close.size();
    }
  }
  return std::string_view::npos;
}

class Expander {
 public:
  explicit Expander(std::vector<std::string>& warnings) : warnings_(warnings) {}

  // 4.2: <!ENTITY [% ] name (literal | ExternalID [NDATA name])>; `text` is the whole declaration.
  void declare(std::string_view text) {
    std::size_t i = 8;  // after "<!ENTITY"
    while (i < text.size() && is_space(text[i])) ++i;
    if (i < text.size() && text[i] == '%') {
      warn_once("parameter entities (<!ENTITY % ...>) are not supported; ignored");
      return;
    }
    const std::size_t name_start = i;
    while (i < text.size() && is_name_char(text[i])) ++i;
    const std::string name(text.substr(name_start, i - name_start));
    while (i < text.size() && is_space(text[i])) ++i;
    if (name.empty() || i >= text.size() || entities_.count(name)) return;  // the first declaration wins
    Entity entity;
    if (text[i] == '"' || text[i] == '\'') {
      const std::size_t end = literal_end(text, i);
      if (end == std::string_view::npos) return;
      const std::string_view value = text.substr(i + 1, end - i - 2);
      // 4.4.5: character references are included in the literal; 4.4.8: entity references bypassed.
      for (std::size_t k = 0; k < value.size();) {
        if (const auto reference = character_reference(value.substr(k))) {
          append_utf8(entity.replacement, reference->first);
          k += reference->second;
        } else {
          entity.replacement += value[k++];
        }
      }
    } else {
      entity.external = true;  // SYSTEM or PUBLIC
    }
    entities_.emplace(name, std::move(entity));
  }

  bool has_entities() const { return !entities_.empty(); }

  // The document after the DOCTYPE with references expanded (5 states: content, tag, attribute value,
  // and the verbatim comment / CDATA / processing-instruction runs).
  Status expand_document(std::string_view text, std::string& out) {
    std::size_t i = 0;
    char quote = 0;  // inside an attribute value quoted with it
    bool in_tag = false;
    while (i < text.size()) {
      const char c = text[i];
      if (!in_tag && c == '<') {
        if (const std::size_t end = verbatim_end(text, i); end != std::string_view::npos) {
          out.append(text.substr(i, end - i));
          i = end;
          continue;
        }
        in_tag = true;
        out += c;
        ++i;
        continue;
      }
      if (in_tag && quote == 0 && (c == '"' || c == '\'')) {
        quote = c;
      } else if (in_tag && c == quote) {
        quote = 0;
      } else if (in_tag && quote == 0 && c == '>') {
        in_tag = false;
      } else if (c == '&' && (!in_tag || quote != 0)) {
        const std::string_view name = entity_reference(text.substr(i));
        if (!name.empty() && !is_predefined(name)) {
          CURVESCAN_PROPAGATE(expand(name, quote != 0, 1, out));
          i += name.size() + 2;
          continue;
        }
      }
      out += c;
      ++i;
    }
    return Status::ok();
  }

 private:
  void warn_once(const std::string& message) {
    if (warned_.insert(message).second) warnings_.push_back(message);
  }

  // Appends the replacement text of entity `name` to `out`, its own references expanded; in an attribute
  // value the characters that would end the value or start a tag are escaped (3.3.3 normalizes the
  // value; it cannot hold '<', 3.1 WFC "No < in Attribute Values").
  Status expand(std::string_view name, bool in_attribute, int depth, std::string& out) {
    const auto found = entities_.find(std::string(name));
    if (found == entities_.end()) {  // undeclared: the XML parser's business
      out += '&';
      out += name;
      out += ';';
      return Status::ok();
    }
    if (found->second.external) {
      warn_once("external entity '&" + std::string(name) +
                ";' is not read (no file or network access); dropped");
      return Status::ok();
    }
    if (depth > kMaxEntityDepth) {
      return Error{ErrorKind::kLimitExceeded, "entity references are nested more than " +
                                                  std::to_string(kMaxEntityDepth) + " deep (at '&" +
                                                  std::string(name) + ";')"};
    }
    if (++references_ > kMaxEntityReferences) {
      return Error{
          ErrorKind::kLimitExceeded,
          "the document expands more than " + std::to_string(kMaxEntityReferences) + " entity references"};
    }
    if (std::find(active_.begin(), active_.end(), found->first) != active_.end()) {
      return Error{ErrorKind::kCorruptInput, "entity '&" + std::string(name) + ";' refers to itself"};
    }
    active_.push_back(found->first);
    const std::string_view replacement = found->second.replacement;
    for (std::size_t k = 0; k < replacement.size();) {
      const std::string_view reference = entity_reference(replacement.substr(k));
      if (!reference.empty() && !is_predefined(reference)) {
        CURVESCAN_PROPAGATE(expand(reference, in_attribute, depth + 1, out));
        k += reference.size() + 2;
        continue;
      }
      const char c = replacement[k++];
      if (++expanded_ > kMaxEntityExpansion) {
        return Error{ErrorKind::kLimitExceeded, "entity expansion exceeds " +
                                                    std::to_string(kMaxEntityExpansion) +
                                                    " bytes (entities that multiply, as in the 'billion "
                                                    "laughs' document, are refused)"};
      }
      if (in_attribute && c == '<') {
        out += "&lt;";
      } else if (in_attribute && c == '"') {
        out += "&quot;";
      } else if (in_attribute && c == '\'') {
        out += "&apos;";
      } else {
        out += c;
      }
    }
    active_.pop_back();
    return Status::ok();
  }

  std::vector<std::string>& warnings_;
  std::unordered_map<std::string, Entity> entities_;
  std::vector<std::string> active_;  // the entities being expanded, outermost first
  std::set<std::string> warned_;
  std::size_t expanded_ = 0;
  std::size_t references_ = 0;
};

// The offset of "<!DOCTYPE" in the prolog (after the XML declaration, comments, processing instructions
// and white space; 2.8), or npos when the document has none.
std::size_t find_doctype(std::string_view xml) {
  std::size_t i = xml.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;  // a UTF-8 byte order mark
  while (i < xml.size()) {
    if (is_space(xml[i])) {
      ++i;
    } else if (xml.substr(i, 4) == "<!--") {
      const std::size_t end = xml.find("-->", i + 4);
      if (end == std::string_view::npos) return end;
      i = end + 3;
    } else if (xml.substr(i, 2) == "<?") {
      const std::size_t end = xml.find("?>", i + 2);
      if (end == std::string_view::npos) return end;
      i = end + 2;
    } else {
      return xml.substr(i, 9) == "<!DOCTYPE" ? i : std::string_view::npos;
    }
  }
  return std::string_view::npos;
}

}  // namespace

Result<std::optional<std::string>> expand_internal_entities(std::string_view xml,
                                                            std::vector<std::string>& warnings) {
  const std::size_t doctype = find_doctype(xml);
  if (doctype == std::string_view::npos) return std::optional<std::string>();
  // 2.8: <!DOCTYPE name ExternalID? [intSubset]? >; the external ID's literals may hold '[' or '>'.
  std::size_t i = doctype + 9;
  while (i < xml.size() && xml[i] != '[' && xml[i] != '>') {
    if (xml[i] == '"' || xml[i] == '\'') {
      i = literal_end(xml, i);
      if (i == std::string_view::npos) return std::optional<std::string>();  // the XML parser reports it
    } else {
      ++i;
    }
  }
  if (i >= xml.size() || xml[i] == '>') return std::optional<std::string>();  // no internal subset
  Expander expander(warnings);
  ++i;
  // 2.8 intSubset: markup declarations, comments, PIs, parameter-entity references and white space.
  while (i < xml.size() && xml[i] != ']') {
    if (xml.substr(i, 2) == "<!" || xml.substr(i, 2) == "<?") {
      const std::size_t end =
          xml[i + 1] == '?'
              ? (xml.find("?>", i) == std::string_view::npos ? std::string_view::npos : xml.find("?>", i) + 2)
              : declaration_end(xml, i);
      if (end == std::string_view::npos) return std::optional<std::string>();
      if (xml.substr(i, 8) == "<!ENTITY") expander.declare(xml.substr(i, end - i));
      i = end;
    } else {
      ++i;
    }
  }
  const std::size_t close = xml.find('>', i);
  if (close == std::string_view::npos || !expander.has_entities()) return std::optional<std::string>();
  std::string out(xml.substr(0, close + 1));
  CURVESCAN_PROPAGATE(expander.expand_document(xml.substr(close + 1), out));
  return std::optional<std::string>(std::move(out));
}

}  // namespace curvescan::svg::detail
