#include "reader_util.h"

#include <algorithm>
#include <charconv>

namespace sweepcdt::io::detail {

void fail(InputErrorKind kind, const std::string& file, Location where, std::string detail) {
  throw InputError(kind, file, std::move(where), std::move(detail));
}

uint64_t plausible_count(uint64_t count, uint64_t min_bytes_each, uint64_t bytes_left, const std::string& what,
                         const std::string& file, const Location& where) {
  if (count > bytes_left)
    fail(InputErrorKind::AbsurdCount, file, where,
         std::to_string(count) + " " + what + " announced, but only " + std::to_string(bytes_left) + " bytes follow");
  return std::min(count, bytes_left / min_bytes_each);
}

void add_point(Soup& soup, double x, double y, double z, const Location& where) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    fail(InputErrorKind::NonFinite, soup.file, where,
         "vertex " + std::to_string(soup.num_points()) + " has a NaN or infinite coordinate");
  if (soup.num_points() >= UINT32_MAX)
    fail(InputErrorKind::AbsurdCount, soup.file, where, "more than 2^32 - 1 vertices");
  soup.points.insert(soup.points.end(), {x, y, z});
}

TextScanner::TextScanner(std::string_view text, const std::string& file, char comment)
    : text_(text), file_(file), comment_(comment) {}

void TextScanner::skip_space_and_comments() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

std::string_view TextScanner::next_token() {
  skip_space_and_comments();
  const std::size_t start = pos_;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || (comment_ != '\0' && c == comment_)) break;
    ++pos_;
  }
  token_line_ = line_;
  return text_.substr(start, pos_ - start);
}

bool TextScanner::next_line(std::vector<std::string_view>& tokens) {
  tokens.clear();
  skip_space_and_comments();
  if (pos_ >= text_.size()) return false;
  const uint64_t this_line = line_;
  while (pos_ < text_.size() && line_ == this_line) {
    tokens.push_back(next_token());
    // Stop at the end of the line: skip blanks and comments but not the newline itself.
    while (pos_ < text_.size() && text_[pos_] != '\n' && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r'))
      ++pos_;
    if (pos_ < text_.size() && comment_ != '\0' && text_[pos_] == comment_) skip_rest_of_line();
    if (pos_ < text_.size() && text_[pos_] == '\n') break;
  }
  token_line_ = this_line;
  return true;
}

void TextScanner::skip_rest_of_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

void TextScanner::fail(InputErrorKind kind, std::string detail) const {
  detail::fail(kind, file_, here(), std::move(detail));
}

namespace {
std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 40;  // a binary blob must not flood the message
  std::string s(token.substr(0, kShown));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) >= 127) c = '?';
  return "'" + s + (token.size() > kShown ? "...'" : "'");
}
}  // namespace

double TextScanner::to_double(std::string_view token, const char* what) const {
  if (token.empty()) fail(InputErrorKind::Truncated, std::string("the file ends where ") + what + " was expected");
  double v = 0;
  const char* first = token.data();
  if (*first == '+') ++first;  // from_chars rejects a leading '+', which C's strtod and the formats allow
  const auto [end, ec] = std::from_chars(first, token.data() + token.size(), v);
  if (ec == std::errc::result_out_of_range)
    fail(InputErrorKind::NonFinite, std::string(what) + " " + quoted(token) + " is out of the range of double");
  if (ec != std::errc() || end != token.data() + token.size())
    fail(InputErrorKind::Syntax, std::string("expected ") + what + ", found " + quoted(token));
  if (!std::isfinite(v)) fail(InputErrorKind::NonFinite, std::string(what) + " " + quoted(token) + " is not finite");
  return v;
}

int64_t TextScanner::to_integer(std::string_view token, const char* what, int64_t min, int64_t max) const {
  if (token.empty()) fail(InputErrorKind::Truncated, std::string("the file ends where ") + what + " was expected");
  int64_t v = 0;
  const char* first = token.data();
  if (*first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, token.data() + token.size(), v);
  if (ec != std::errc() || end != token.data() + token.size())
    fail(InputErrorKind::Syntax, std::string("expected ") + what + " (an integer), found " + quoted(token));
  if (v < min || v > max)
    fail(InputErrorKind::Syntax, std::string(what) + " " + std::to_string(v) + " is outside [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

}  // namespace sweepcdt::io::detail
