// Internal helpers shared by the readers: error raising, a text scanner that knows line numbers, a
// bounds-checked binary cursor, and the count-versus-file-size guard that runs before any reserve().
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "sweepcdt/io/error.h"
#include "sweepcdt/io/soup.h"

namespace sweepcdt::io::detail {

[[noreturn]] void fail(InputErrorKind kind, const std::string& file, Location where, std::string detail);

// A count announced by a file: AbsurdCount if the remaining bytes could not hold that many items even
// at one byte each. Returns how many items to reserve room for: no more than the remaining bytes can
// hold at `min_bytes_each`, so a count that is merely too large ends in Truncated while reading,
// never in a huge allocation.
uint64_t plausible_count(uint64_t count, uint64_t min_bytes_each, uint64_t bytes_left, const std::string& what,
                         const std::string& file, const Location& where);

// Appends a point; NonFinite if a coordinate is NaN or infinite.
void add_point(Soup& soup, double x, double y, double z, const Location& where);

// Text cut into whitespace-separated tokens; `comment` (if not '\0') starts a comment to end of line.
class TextScanner {
 public:
  TextScanner(std::string_view text, const std::string& file, char comment);

  // The next token, or an empty view at the end of the text.
  std::string_view next_token();
  // The tokens of the next line that has any; false at the end of the text.
  bool next_line(std::vector<std::string_view>& tokens);
  void skip_rest_of_line();

  uint64_t line() const { return token_line_; }  // line of the last token returned (1-based)
  uint64_t bytes_left() const { return text_.size() - pos_; }
  std::size_t offset() const { return pos_; }
  const std::string& file() const { return file_; }
  Location here() const { return Location::line(token_line_); }

  [[noreturn]] void fail(InputErrorKind kind, std::string detail) const;
  // Parses a token as a finite double (Syntax or NonFinite otherwise).
  double to_double(std::string_view token, const char* what) const;
  // Parses a token as an integer in [min, max] (Syntax otherwise, IndexOutOfRange is the caller's).
  int64_t to_integer(std::string_view token, const char* what, int64_t min = INT64_MIN, int64_t max = INT64_MAX) const;

 private:
  void skip_space_and_comments();
  std::string_view text_;
  const std::string& file_;
  char comment_;
  std::size_t pos_ = 0;
  uint64_t line_ = 1;        // line at pos_
  uint64_t token_line_ = 1;  // line of the last token
};

// Reads little- or big-endian scalars; Truncated when the data runs out.
class ByteReader {
 public:
  ByteReader(std::string_view data, const std::string& file, std::size_t start = 0)
      : data_(data), file_(file), pos_(start) {}
  void need(std::size_t n, const char* what) const {
    if (data_.size() - pos_ < n)
      fail(InputErrorKind::Truncated, file_, Location::byte(pos_),
           std::string("the file ends inside ") + what + " (" + std::to_string(n) + " bytes needed, " +
               std::to_string(data_.size() - pos_) + " left)");
  }
  template <class T>
  T read(bool big_endian, const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if (big_endian != (std::endian::native == std::endian::big)) v = byteswap(v);
    return v;
  }
  void skip(std::size_t n, const char* what) {
    need(n, what);
    pos_ += n;
  }
  std::size_t offset() const { return pos_; }
  std::size_t bytes_left() const { return data_.size() - pos_; }

 private:
  template <class T>
  static T byteswap(T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    std::memcpy(&v, b, sizeof(T));
    return v;
  }
  std::string_view data_;
  const std::string& file_;
  std::size_t pos_;
};

// Triangulates polygon `ids` (k >= 3 point ids into soup.points) and appends the triangles to
// soup.triangles. A triangle is appended as is (degenerate ones are the surface check's business);
// larger polygons must be planar — decided exactly with orient<3> — and simple, else BadPolygon.
// Convex polygons are fanned; others are ear-clipped in their plane with exact orientation tests.
void add_polygon(Soup& soup, const std::vector<uint32_t>& ids, const Location& where);

// The per-format readers (read_*.cpp). `soup.file` is set; they fill points and triangles.
void read_off(std::string_view bytes, Soup& soup);
void read_stl_ascii(std::string_view bytes, Soup& soup);
void read_stl_binary(std::string_view bytes, Soup& soup);
void read_obj(std::string_view bytes, Soup& soup);
void read_ply(std::string_view bytes, Soup& soup);
void read_gltf(std::string_view bytes, Soup& soup, bool binary);
void read_draco(std::string_view bytes, Soup& soup);

}  // namespace sweepcdt::io::detail
