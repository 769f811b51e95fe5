// The CSS tokenizer (tokenizer.h). Section numbers refer to CSS Syntax Module Level 3.
#include "tokenizer.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>

#include "curvescan/text/utf8.h"

namespace curvescan::svg::css {
namespace {

constexpr char32_t kReplacement = 0xFFFD;

// 3.3 "Preprocessing the input stream".
std::string preprocess(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\r') {
      out += '\n';
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
    } else if (c == '\f') {
      out += '\n';
    } else if (c == '\0') {
      out += "\xEF\xBF\xBD";  // U+FFFD
    } else {
      out += c;
    }
  }
  return out;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_hex_digit(char c) {
  return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}
std::uint32_t hex_value(char c) {
  return static_cast<std::uint32_t>(is_digit(c) ? c - '0' : (c | 0x20) - 'a' + 10);
}
bool is_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
// 4.2: ident-start code point: a letter, a non-ASCII code point or '_'.
bool is_name_start(char c) {
  return is_letter(c) || static_cast<unsigned char>(c) >= 0x80 || c == '_';
}
bool is_name(char c) {
  return is_name_start(c) || is_digit(c) || c == '-';
}
bool is_whitespace(char c) {
  return c == ' ' || c == '\t' || c == '\n';
}
// 4.2: non-printable code point.
bool is_non_printable(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u <= 0x08 || u == 0x0B || (u >= 0x0E && u <= 0x1F) || u == 0x7F;
}

class Tokenizer {
 public:
  explicit Tokenizer(std::string source) { list_.source = std::move(source); }

  TokenList run(std::size_t max_tokens) {
    while (pos_ < text().size()) {
      if (list_.tokens.size() >= max_tokens) {
        list_.truncated = true;
        break;
      }
      const std::size_t begin = pos_;
      Token token = consume_token();
      if (skipped_comment_) {
        skipped_comment_ = false;
        continue;
      }
      token.begin = begin;
      token.end = pos_;
      list_.tokens.push_back(std::move(token));
    }
    return std::move(list_);
  }

 private:
  std::string_view text() const { return list_.source; }
  char at(std::size_t offset) const { return pos_ + offset < text().size() ? text()[pos_ + offset] : '\0'; }
  bool has(std::size_t offset) const { return pos_ + offset < text().size(); }

  static Token make(TokenType type, std::string value = {}) {
    Token token;
    token.type = type;
    token.value = std::move(value);
    return token;
  }

  // 4.3.8 "Check if two code points are a valid escape".
  bool valid_escape(std::size_t offset) const {
    return has(offset) && at(offset) == '\\' && (!has(offset + 1) || at(offset + 1) != '\n');
  }
  // 4.3.9 "Check if three code points would start an ident sequence".
  bool starts_ident(std::size_t offset) const {
    const char c = at(offset);
    if (!has(offset)) return false;
    if (c == '-') {
      return (has(offset + 1) && (is_name_start(at(offset + 1)) || at(offset + 1) == '-')) ||
             valid_escape(offset + 1);
    }
    if (is_name_start(c)) return true;
    return valid_escape(offset);
  }
  // 4.3.10 "Check if three code points would start a number".
  bool starts_number(std::size_t offset) const {
    const char c = at(offset);
    if (!has(offset)) return false;
    if (c == '+' || c == '-') {
      if (is_digit(at(offset + 1)) && has(offset + 1)) return true;
      return at(offset + 1) == '.' && has(offset + 2) && is_digit(at(offset + 2));
    }
    if (c == '.') return has(offset + 1) && is_digit(at(offset + 1));
    return is_digit(c);
  }

  // 4.3.7 "Consume an escaped code point"; pos_ is just after the backslash.
  void consume_escape(std::string& out) {
    if (!has(0)) {
      append_utf8(out, kReplacement);  // EOF after '\': a parse error, U+FFFD
      return;
    }
    if (is_hex_digit(at(0))) {
      std::uint32_t value = 0;
      int digits = 0;
      while (digits < 6 && has(0) && is_hex_digit(at(0))) {
        value = value * 16 + hex_value(at(0));
        ++pos_;
        ++digits;
      }
      if (has(0) && is_whitespace(at(0))) ++pos_;
      if (value == 0 || (value >= 0xD800 && value <= 0xDFFF) || value > 0x10FFFF) value = kReplacement;
      append_utf8(out, static_cast<char32_t>(value));
      return;
    }
    out += at(0);
    ++pos_;
  }

  // 4.3.11 "Consume an ident sequence".
  std::string consume_ident_sequence() {
    std::string out;
    while (has(0)) {
      if (is_name(at(0))) {
        out += at(0);
        ++pos_;
      } else if (valid_escape(0)) {
        ++pos_;
        consume_escape(out);
      } else {
        break;
      }
    }
    return out;
  }

  // 4.3.12 "Consume a number": the value and whether it is an integer.
  std::pair<double, bool> consume_number() {
    const std::size_t start = pos_;
    bool integer = true;
    if (at(0) == '+' || at(0) == '-') ++pos_;
    while (has(0) && is_digit(at(0))) ++pos_;
    if (at(0) == '.' && has(1) && is_digit(at(1))) {
      integer = false;
      pos_ += 2;
      while (has(0) && is_digit(at(0))) ++pos_;
    }
    if ((at(0) == 'e' || at(0) == 'E') &&
        ((has(1) && is_digit(at(1))) || ((at(1) == '+' || at(1) == '-') && has(2) && is_digit(at(2))))) {
      integer = false;
      pos_ += is_digit(at(1)) ? 1 : 2;
      while (has(0) && is_digit(at(0))) ++pos_;
    }
    // The text is a valid decimal floating-point literal by construction; std::strtod handles a huge
    // exponent by returning +-HUGE_VAL, which the property parsers then refuse as out of range.
    std::string_view digits = text().substr(start, pos_ - start);
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto parsed = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (parsed.ec == std::errc::result_out_of_range)
      value = std::strtod(std::string(digits).c_str(), nullptr);
    return {value, integer};
  }

  // 4.3.3 "Consume a numeric token".
  Token consume_numeric() {
    const auto [value, integer] = consume_number();
    Token token;
    token.number = value;
    token.is_integer = integer;
    if (starts_ident(0)) {
      token.type = TokenType::kDimension;
      token.value = consume_ident_sequence();
    } else if (at(0) == '%' && has(0)) {
      ++pos_;
      token.type = TokenType::kPercentage;
    } else {
      token.type = TokenType::kNumber;
    }
    return token;
  }

  // 4.3.5 "Consume a string token"; pos_ is after the opening quote.
  Token consume_string(char quote) {
    std::string value;
    while (has(0)) {
      const char c = at(0);
      if (c == quote) {
        ++pos_;
        return make(TokenType::kString, std::move(value));
      }
      if (c == '\n') return make(TokenType::kBadString);  // the newline is not consumed
      ++pos_;
      if (c == '\\') {
        if (!has(0)) continue;  // EOF after '\': nothing
        if (at(0) == '\n') {
          ++pos_;  // an escaped newline continues the string
          continue;
        }
        consume_escape(value);
        continue;
      }
      value += c;
    }
    return make(TokenType::kString, std::move(value));  // EOF: a parse error, the string as read
  }

  // 4.3.14 "Consume the remnants of a bad url".
  void consume_bad_url_remnants() {
    while (has(0)) {
      const char c = at(0);
      ++pos_;
      if (c == ')') return;
      if (c == '\\' && has(0) && at(0) != '\n') {
        std::string ignored;
        consume_escape(ignored);
      }
    }
  }

  // 4.3.6 "Consume a url token"; pos_ is after "url(".
  Token consume_url() {
    while (has(0) && is_whitespace(at(0))) ++pos_;
    std::string value;
    while (true) {
      if (!has(0)) return make(TokenType::kUrl, std::move(value));
      const char c = at(0);
      if (c == ')') {
        ++pos_;
        return make(TokenType::kUrl, std::move(value));
      }
      if (is_whitespace(c)) {
        while (has(0) && is_whitespace(at(0))) ++pos_;
        if (!has(0) || at(0) == ')') {
          if (has(0)) ++pos_;
          return make(TokenType::kUrl, std::move(value));
        }
        consume_bad_url_remnants();
        return make(TokenType::kBadUrl);
      }
      if (c == '"' || c == '\'' || c == '(' || is_non_printable(c)) {
        consume_bad_url_remnants();
        return make(TokenType::kBadUrl);
      }
      if (c == '\\') {
        if (valid_escape(0)) {
          ++pos_;
          consume_escape(value);
          continue;
        }
        consume_bad_url_remnants();
        return make(TokenType::kBadUrl);
      }
      value += c;
      ++pos_;
    }
  }

  // 4.3.4 "Consume an ident-like token".
  Token consume_ident_like() {
    std::string name = consume_ident_sequence();
    if (at(0) == '(' && has(0)) {
      ++pos_;
      if (name.size() == 3 && (name[0] | 0x20) == 'u' && (name[1] | 0x20) == 'r' && (name[2] | 0x20) == 'l') {
        // url( followed by a quoted string is a function token; otherwise a url token.
        std::size_t look = 0;
        while (has(look) && is_whitespace(at(look))) ++look;
        if (has(look) && (at(look) == '"' || at(look) == '\''))
          return make(TokenType::kFunction, std::move(name));
        return consume_url();
      }
      return make(TokenType::kFunction, std::move(name));
    }
    return make(TokenType::kIdent, std::move(name));
  }

  // 4.3.1 "Consume a token".
  Token consume_token() {
    const char c = at(0);
    // 4.3.2 "Consume comments".
    if (c == '/' && at(1) == '*' && has(1)) {
      const std::size_t close = text().find("*/", pos_ + 2);
      pos_ = close == std::string_view::npos ? text().size() : close + 2;
      skipped_comment_ = true;
      return {};
    }
    if (is_whitespace(c)) {
      while (has(0) && is_whitespace(at(0))) ++pos_;
      return make(TokenType::kWhitespace);
    }
    if (c == '"' || c == '\'') {
      ++pos_;
      return consume_string(c);
    }
    if (c == '#') {
      if (has(1) && (is_name(at(1)) || valid_escape(1))) {
        ++pos_;
        const bool id = starts_ident(0);
        Token token = make(TokenType::kHash, consume_ident_sequence());
        token.is_id_hash = id;
        return token;
      }
      ++pos_;
      return make(TokenType::kDelim, "#");
    }
    if (c == '+' || c == '.') {
      if (starts_number(0)) return consume_numeric();
      ++pos_;
      return make(TokenType::kDelim, std::string(1, c));
    }
    if (c == '-') {
      if (starts_number(0)) return consume_numeric();
      if (at(1) == '-' && at(2) == '>' && has(2)) {
        pos_ += 3;
        return make(TokenType::kCdc);
      }
      if (starts_ident(0)) return consume_ident_like();
      ++pos_;
      return make(TokenType::kDelim, "-");
    }
    if (c == '<' && text().substr(pos_, 4) == "<!--") {
      pos_ += 4;
      return make(TokenType::kCdo);
    }
    if (c == '@') {
      ++pos_;
      if (starts_ident(0)) return make(TokenType::kAtKeyword, consume_ident_sequence());
      return make(TokenType::kDelim, "@");
    }
    if (c == '\\') {
      if (valid_escape(0)) return consume_ident_like();
      ++pos_;
      return make(TokenType::kDelim, "\\");  // a parse error
    }
    if (is_digit(c)) return consume_numeric();
    if (is_name_start(c)) return consume_ident_like();
    ++pos_;
    switch (c) {
      case '(':
        return make(TokenType::kOpenParen);
      case ')':
        return make(TokenType::kCloseParen);
      case '[':
        return make(TokenType::kOpenSquare);
      case ']':
        return make(TokenType::kCloseSquare);
      case '{':
        return make(TokenType::kOpenCurly);
      case '}':
        return make(TokenType::kCloseCurly);
      case ',':
        return make(TokenType::kComma);
      case ':':
        return make(TokenType::kColon);
      case ';':
        return make(TokenType::kSemicolon);
      default:
        return make(TokenType::kDelim, std::string(1, c));
    }
  }

  TokenList list_;
  std::size_t pos_ = 0;
  bool skipped_comment_ = false;
};

}  // namespace

TokenList tokenize(std::string_view text, std::size_t max_tokens) {
  return Tokenizer(preprocess(text)).run(max_tokens);
}

std::string serialize_tokens(const TokenList& list, std::size_t first, std::size_t last) {
  std::string out;
  for (std::size_t i = first; i < last; ++i) {
    const Token& token = list.tokens[i];
    // A comment between two tokens left a gap in the offsets: keep them apart.
    if (i > first && token.begin != list.tokens[i - 1].end && !out.empty() && out.back() != ' ') out += ' ';
    switch (token.type) {
      case TokenType::kWhitespace:
        out += ' ';
        break;
      case TokenType::kIdent:
        out += token.value;
        break;
      case TokenType::kFunction:
        out += token.value + "(";
        break;
      case TokenType::kAtKeyword:
        out += "@" + token.value;
        break;
      case TokenType::kHash:
        out += "#" + token.value;
        break;
      case TokenType::kUrl:
        out += "url(" + token.value + ")";
        break;
      // Strings, numbers and punctuation as written (strings keep their quotes and escapes, which the
      // font-family parser reads).
      default:
        out += std::string_view(list.source).substr(token.begin, token.end - token.begin);
    }
  }
  return out;
}

}  // namespace curvescan::svg::css
