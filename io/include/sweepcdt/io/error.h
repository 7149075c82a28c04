// Typed errors of sweepcdt::io. Every message is one line that names the file and where in it the
// problem is (line, byte offset or element index), so a user can open the file and look.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "sweepcdt/error.h"

namespace sweepcdt::io {

// Where in a file a problem was found.
struct Location {
  enum class Unit : uint8_t { None, Line, Byte, Element };
  Unit unit = Unit::None;
  uint64_t index = 0;    // 1-based line number, 0-based byte offset or 0-based element index
  std::string element;   // for Unit::Element: what is counted ("face", "accessor", "primitive", ...)

  static Location none() { return {}; }
  static Location line(uint64_t n) { return {Unit::Line, n, {}}; }
  static Location byte(uint64_t offset) { return {Unit::Byte, offset, {}}; }
  static Location of(std::string element, uint64_t index) { return {Unit::Element, index, std::move(element)}; }
  std::string to_string() const;  // "line 12", "byte 84", "face 3", or ""
};

enum class InputErrorKind : uint8_t {
  Unreadable,        // the file cannot be opened or read (for writers: written)
  UnknownFormat,     // the content matches no supported format
  Unsupported,       // a variant of the format this reader does not handle (named in the message)
  Syntax,            // a token that is not what the format requires
  Truncated,         // the data ends before what the header or structure announces
  SizeMismatch,      // a count disagrees with the file size or a declared length
  AbsurdCount,       // a count that the file cannot possibly hold (checked before any allocation)
  NonFinite,         // NaN or infinite coordinate
  IndexOutOfRange,   // a face names a vertex (or a structure an element) that does not exist
  BadPolygon,        // a polygon that is non-planar, degenerate or not simple, so it cannot be triangulated
};

const char* to_string(InputErrorKind kind);

// The file is malformed: "FILE:LINE: detail", "FILE: byte N: detail" or "FILE: face N: detail".
class InputError : public Error {
 public:
  InputError(InputErrorKind kind, std::string file, Location where, std::string detail);
  InputErrorKind kind() const { return kind_; }
  const std::string& file() const { return file_; }
  const Location& where() const { return where_; }
  const std::string& detail() const { return detail_; }

 private:
  InputErrorKind kind_;
  std::string file_;
  Location where_;
  std::string detail_;
};

// What is wrong with a well-formed surface as the boundary of a volume.
enum class SurfaceProblemKind : uint8_t {
  DegenerateTriangle,  // a triangle with a repeated vertex or exactly collinear corners (zero area)
  DuplicateTriangle,   // two triangles with the same three vertices
  BoundaryEdge,        // an edge with one triangle: the surface is open
  NonManifoldEdge,     // an edge with more than two triangles
  NonManifoldVertex,   // a vertex whose triangles form more than one fan (a pinch)
  NonOrientable,       // a shell whose triangles cannot be oriented consistently
  SelfIntersection,    // two triangles that meet other than in their shared vertices/edge
};
inline constexpr int kSurfaceProblemKinds = 7;

const char* to_string(SurfaceProblemKind kind);

struct SurfaceProblem {
  SurfaceProblemKind kind;
  std::vector<uint64_t> elements;  // triangle indices, or vertex indices for edges and vertices
  std::string message;             // one line
};

// The surface does not bound a volume. what(): one line per problem, first ones of each kind, with the
// count of each kind.
class SurfaceError : public Error {
 public:
  SurfaceError(std::string file, std::vector<SurfaceProblem> problems, std::vector<uint64_t> counts);
  const std::string& file() const { return file_; }
  const std::vector<SurfaceProblem>& problems() const { return problems_; }
  uint64_t count(SurfaceProblemKind kind) const { return counts_[static_cast<int>(kind)]; }

 private:
  std::string file_;
  std::vector<SurfaceProblem> problems_;
  std::vector<uint64_t> counts_;  // kSurfaceProblemKinds entries
};

}  // namespace sweepcdt::io
