// The tokenizer every text mesh format shares (OFF, OBJ, ASCII PLY, ASCII STL):
// one pass over the whole file held in memory, tokens as string_views,
// numbers through std::from_chars, the line number kept for error messages.
#pragma once

#include "reebkit/core/error.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace reebkit {

/// Tokens are separated by blanks (space, tab, CR, VT, FF); '\n' ends a line.
class TextScanner {
 public:
  struct Options {
    char comment = '\0';             ///< starts a comment running to the end of the line ('\0' = none)
    bool line_continuation = false;  ///< a '\' right before the line break joins two lines (OBJ)
  };

  /// `text` must outlive the scanner; `source` names it in error messages.
  TextScanner(std::string_view text, std::string source, Options options);

  /// 1-based line of the scan position.
  std::uint64_t line() const { return line_; }
  /// Bytes from the scan position to the end of the text.
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - pos_); }

  /// Skips blanks, comments and line breaks up to the next token.
  /// Returns false when only those remain.
  bool skip_to_token();
  /// The next token of the current line, or an empty view when the line has no more.
  std::string_view token_on_line();
  /// The next token, crossing line breaks; empty at the end of the text.
  std::string_view token();
  /// Discards the rest of the current line and its line break.
  void next_line();

  /// The next token of the current line as a number / an integer. `what`
  /// names the expected value in the error ("expected <what>, found ...").
  double number_on_line(const char* what);
  std::int64_t integer_on_line(const char* what);

  /// `token` as a number / integer; throws quoting the token.
  double to_number(std::string_view token, const char* what) const;
  std::int64_t to_integer(std::string_view token, const char* what) const;

  /// Throws MeshFileError(source, line, problem).
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  void skip_blanks();
  [[noreturn]] void fail_expected(const char* what, std::string_view found) const;

  enum CharClass : std::uint8_t { kWord, kBlank, kNewline, kComment, kBackslash };

  const char* pos_;
  const char* end_;
  std::string source_;
  std::uint64_t line_ = 1;
  std::array<CharClass, 256> classes_{};
};

/// Quotes a token for an error message, shortened when long and with
/// non-printable bytes escaped.
std::string quoted(std::string_view token);

}  // namespace reebkit
