#include "reebkit/io/text_scanner.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace reebkit {

namespace {

/// std::from_chars rejects a leading '+', which some writers emit.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token.front() == '+') token.remove_prefix(1);
  return token;
}

template <typename T>
bool parse_whole(std::string_view token, T& value) {
  token = without_plus(token);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

}  // namespace

std::string quoted(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    }
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

TextScanner::TextScanner(std::string_view text, std::string source, Options options)
    : pos_(text.empty() ? "" : text.data()),  // never a null pointer, even for an empty view
      end_(pos_ + text.size()),
      source_(std::move(source)) {
  classes_.fill(kWord);
  for (const char c : {' ', '\t', '\r', '\v', '\f'}) classes_[static_cast<unsigned char>(c)] = kBlank;
  classes_['\n'] = kNewline;
  if (options.comment != '\0') classes_[static_cast<unsigned char>(options.comment)] = kComment;
  if (options.line_continuation) classes_['\\'] = kBackslash;
}

void TextScanner::skip_blanks() {
  while (pos_ < end_) {
    switch (classes_[static_cast<unsigned char>(*pos_)]) {
      case kBlank: ++pos_; break;
      case kComment: {
        const void* newline = std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_));
        pos_ = newline ? static_cast<const char*>(newline) : end_;
        return;
      }
      case kBackslash: {
        const char* after = pos_ + 1;
        while (after < end_ && *after == '\r') ++after;
        if (after == end_ || *after != '\n') return;  // a lone '\' is a token
        pos_ = after + 1;
        ++line_;
        break;
      }
      default: return;
    }
  }
}

bool TextScanner::skip_to_token() {
  for (;;) {
    skip_blanks();
    if (pos_ == end_) return false;
    if (*pos_ != '\n') return true;
    ++pos_;
    ++line_;
  }
}

std::string_view TextScanner::token_on_line() {
  skip_blanks();
  if (pos_ == end_ || *pos_ == '\n') return {};
  const char* start = pos_++;
  while (pos_ < end_ && classes_[static_cast<unsigned char>(*pos_)] == kWord) ++pos_;
  return {start, static_cast<std::size_t>(pos_ - start)};
}

std::string_view TextScanner::token() { return skip_to_token() ? token_on_line() : std::string_view(); }

void TextScanner::next_line() {
  for (;;) {
    const char* from = pos_;
    const void* newline = std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_));
    if (!newline) {
      pos_ = end_;
      return;
    }
    const char* before = static_cast<const char*>(newline);
    pos_ = before + 1;
    ++line_;
    if (classes_['\\'] != kBackslash) return;
    while (before > from && before[-1] == '\r') --before;
    if (before == from || before[-1] != '\\') return;  // not continued on the next line
  }
}

double TextScanner::number_on_line(const char* what) { return to_number(token_on_line(), what); }

std::int64_t TextScanner::integer_on_line(const char* what) { return to_integer(token_on_line(), what); }

double TextScanner::to_number(std::string_view token, const char* what) const {
  double value = 0;
  if (parse_whole(token, value)) return value;
  // from_chars refuses numbers beyond the range of a double; strtod rounds
  // them to +-0 or +-inf, as any other reader would.
  const std::string text(without_plus(token));
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno != ERANGE) fail_expected(what, token);
  return value;
}

std::int64_t TextScanner::to_integer(std::string_view token, const char* what) const {
  std::int64_t value = 0;
  if (!parse_whole(token, value)) fail_expected(what, token);
  return value;
}

void TextScanner::fail(const std::string& problem) const { throw MeshFileError(source_, line_, problem); }

void TextScanner::fail_expected(const char* what, std::string_view found) const {
  fail(std::string("expected ") + what + ", found " +
       (found.empty() ? std::string(pos_ == end_ ? "end of file" : "end of line") : quoted(found)));
}

}  // namespace reebkit
