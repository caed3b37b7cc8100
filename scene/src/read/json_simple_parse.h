// A fast path for the JSON that Lintel's writer and most exporters produce: plain ASCII strings
// without escapes, numbers, literals, objects and arrays. It drives the same SAX handler as
// nlohmann's parser and gives it the same events, with nlohmann's number rules (an integer is
// number_unsigned, or number_integer when negative; anything with a fraction or an exponent is
// number_float, correctly rounded as strtod rounds it). nlohmann's lexer, which copies every
// character into a token buffer and tracks lines and columns for its messages, was most of
// loading an imported level.
//
// It never reports an error: on anything outside that subset (an escape, a byte >= 0x80 or a
// control character in a string, an integer beyond 64 bits, a float beyond double), on malformed
// text, and on text beyond the limits of json_bounded.h it returns false, and the caller parses the
// text again with nlohmann, which gives the DOM or the message it always gave. The handler may
// then hold part of a document and must be discarded.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <system_error>

namespace lintel::scene_read {

template <class Sax>
class SimpleJsonParser {
 public:
  // The limits are those of json_bounds_error, counted the same way: nesting depth of objects and
  // arrays, and values as 1 + every '{', '[' and ','.
  SimpleJsonParser(const char* text, size_t size, Sax& sax, size_t max_depth, size_t max_values)
      : p_(text), end_(text + size), sax_(sax), max_depth_(max_depth), max_values_(max_values) {}

  // True when the whole text is one value of the subset, within the limits, and `sax` accepted
  // every event.
  bool parse() {
    skip_space();
    if (!value(0)) return false;
    skip_space();
    return p_ == end_;
  }

 private:
  static bool digit(char c) { return c >= '0' && c <= '9'; }

  void skip_space() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
  }

  bool value(size_t depth) {
    if (p_ == end_) return false;
    switch (*p_) {
      case '{':
        return object(depth + 1);
      case '[':
        return array(depth + 1);
      case '"': {
        std::string s;
        return string(s) && sax_.string(s);
      }
      case 't':
        return literal("true", 4) && sax_.boolean(true);
      case 'f':
        return literal("false", 5) && sax_.boolean(false);
      case 'n':
        return literal("null", 4) && sax_.null();
      default:
        return number();
    }
  }

  // A '{' or '[' at depth `depth` (the outermost is 1): one more value, maybe too deep.
  bool open(size_t depth) {
    ++p_;
    return depth <= max_depth_ && ++values_ <= max_values_;
  }

  // After an element: ',' (one more value) and true, or the closing `close` and false in `more`.
  bool next(char close, bool& more) {
    skip_space();
    if (p_ == end_) return false;
    if (*p_ == ',') {
      ++p_;
      more = true;
      return ++values_ <= max_values_;
    }
    more = false;
    if (*p_ != close) return false;
    ++p_;
    return true;
  }

  bool object(size_t depth) {
    if (!open(depth) || !sax_.start_object(size_t(-1))) return false;
    skip_space();
    if (p_ != end_ && *p_ == '}') {
      ++p_;
      return sax_.end_object();
    }
    for (bool more = true; more;) {
      skip_space();
      std::string key;
      if (p_ == end_ || *p_ != '"' || !string(key)) return false;
      skip_space();
      if (p_ == end_ || *p_ != ':') return false;
      ++p_;
      skip_space();
      if (!sax_.key(key) || !value(depth) || !next('}', more)) return false;
    }
    return sax_.end_object();
  }

  bool array(size_t depth) {
    if (!open(depth) || !sax_.start_array(size_t(-1))) return false;
    skip_space();
    if (p_ != end_ && *p_ == ']') {
      ++p_;
      return sax_.end_array();
    }
    for (bool more = true; more;) {
      skip_space();
      if (!value(depth) || !next(']', more)) return false;
    }
    return sax_.end_array();
  }

  // A string of printable ASCII without escapes; `p_` is at the opening quote.
  bool string(std::string& out) {
    const char* first = ++p_;
    while (p_ != end_) {
      const auto c = static_cast<unsigned char>(*p_);
      if (c == '"') {
        out.assign(first, p_);
        ++p_;
        return true;
      }
      if (c == '\\' || c < 0x20 || c >= 0x80) return false;  // nlohmann decodes and validates these
      ++p_;
    }
    return false;
  }

  bool literal(const char* word, size_t length) {
    if (size_t(end_ - p_) < length) return false;
    for (size_t i = 0; i < length; ++i)
      if (p_[i] != word[i]) return false;
    p_ += length;
    return true;
  }

  // JSON's grammar: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  bool number() {
    const char* first = p_;
    const bool negative = *p_ == '-';
    if (negative) ++p_;
    const char* digits = p_;
    if (p_ == end_ || !digit(*p_)) return false;
    if (*p_ == '0')
      ++p_;
    else
      while (p_ != end_ && digit(*p_)) ++p_;
    const char* digits_end = p_;
    bool is_float = false;
    if (p_ != end_ && *p_ == '.') {
      is_float = true;
      if (++p_ == end_ || !digit(*p_)) return false;
      while (p_ != end_ && digit(*p_)) ++p_;
    }
    if (p_ != end_ && (*p_ == 'e' || *p_ == 'E')) {
      is_float = true;
      if (++p_ != end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !digit(*p_)) return false;
      while (p_ != end_ && digit(*p_)) ++p_;
    }
    if (!is_float) {
      uint64_t v = 0;
      for (const char* d = digits; d != digits_end; ++d) {
        const auto digit_value = uint64_t(*d - '0');
        if (v > (UINT64_MAX - digit_value) / 10) return false;  // nlohmann makes it a float
        v = v * 10 + digit_value;
      }
      if (!negative) return sax_.number_unsigned(v);
      if (v > uint64_t(INT64_MAX) + 1) return false;  // below INT64_MIN: a float for nlohmann
      return sax_.number_integer(v == uint64_t(INT64_MAX) + 1 ? INT64_MIN : -int64_t(v));
    }
    double d = 0.0;
    const auto [end, error] = std::from_chars(first, p_, d);
    if (error != std::errc() || end != p_ || !std::isfinite(d)) return false;
    return sax_.number_float(d, no_token_);  // the handler gets no token text on this path
  }

  const char* p_;
  const char* end_;
  Sax& sax_;
  size_t max_depth_;
  size_t max_values_;
  size_t values_ = 1;
  std::string no_token_;
};

// SimpleJsonParser(text, size, sax, max_depth, max_values).parse().
template <class Sax>
bool parse_simple_json(const char* text, size_t size, Sax& sax, size_t max_depth, size_t max_values) {
  return SimpleJsonParser<Sax>(text, size, sax, max_depth, max_values).parse();
}

}  // namespace lintel::scene_read
