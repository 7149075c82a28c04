#include "sweepcdt/io/error.h"

#include "sweepcdt/io/soup.h"

namespace sweepcdt::io {

std::string Location::to_string() const {
  switch (unit) {
    case Unit::None: return {};
    case Unit::Line: return "line " + std::to_string(index);
    case Unit::Byte: return "byte " + std::to_string(index);
    case Unit::Element: return element + " " + std::to_string(index);
  }
  return {};
}

const char* to_string(InputErrorKind kind) {
  switch (kind) {
    case InputErrorKind::Unreadable: return "unreadable";
    case InputErrorKind::UnknownFormat: return "unknown-format";
    case InputErrorKind::Unsupported: return "unsupported";
    case InputErrorKind::Syntax: return "syntax";
    case InputErrorKind::Truncated: return "truncated";
    case InputErrorKind::SizeMismatch: return "size-mismatch";
    case InputErrorKind::AbsurdCount: return "absurd-count";
    case InputErrorKind::NonFinite: return "non-finite";
    case InputErrorKind::IndexOutOfRange: return "index-out-of-range";
    case InputErrorKind::BadPolygon: return "bad-polygon";
  }
  return "unknown";
}

const char* to_string(SurfaceProblemKind kind) {
  switch (kind) {
    case SurfaceProblemKind::DegenerateTriangle: return "degenerate-triangle";
    case SurfaceProblemKind::DuplicateTriangle: return "duplicate-triangle";
    case SurfaceProblemKind::BoundaryEdge: return "boundary-edge";
    case SurfaceProblemKind::NonManifoldEdge: return "non-manifold-edge";
    case SurfaceProblemKind::NonManifoldVertex: return "non-manifold-vertex";
    case SurfaceProblemKind::NonOrientable: return "non-orientable";
    case SurfaceProblemKind::SelfIntersection: return "self-intersection";
  }
  return "unknown";
}

const char* to_string(Format format) {
  switch (format) {
    case Format::Off: return "OFF";
    case Format::StlAscii: return "STL ascii";
    case Format::StlBinary: return "STL binary";
    case Format::Obj: return "OBJ";
    case Format::Ply: return "PLY";
    case Format::Gltf: return "glTF";
    case Format::Glb: return "GLB";
    case Format::Draco: return "Draco";
  }
  return "unknown";
}

namespace {

// "FILE:12: detail" for lines (as compilers do, so editors jump there), "FILE: byte 84: detail" else.
std::string describe(const std::string& file, const Location& where, const std::string& detail) {
  if (where.unit == Location::Unit::Line) return file + ":" + std::to_string(where.index) + ": " + detail;
  if (where.unit == Location::Unit::None) return file + ": " + detail;
  return file + ": " + where.to_string() + ": " + detail;
}

std::string describe(const std::string& file, const std::vector<SurfaceProblem>& problems, const std::vector<uint64_t>& counts) {
  if (problems.empty()) return file + ": no triangles: nothing bounds a volume";
  std::string s = file + ": not a closed surface bounding a volume:";
  for (int k = 0; k < kSurfaceProblemKinds; ++k) {
    if (counts[k] == 0) continue;
    s += " " + std::to_string(counts[k]) + " " + to_string(static_cast<SurfaceProblemKind>(k));
  }
  for (const auto& p : problems) s += "\n" + file + ": " + p.message;
  return s;
}

}  // namespace

InputError::InputError(InputErrorKind kind, std::string file, Location where, std::string detail)
    : Error(describe(file, where, detail)), kind_(kind), file_(std::move(file)), where_(std::move(where)), detail_(std::move(detail)) {}

SurfaceError::SurfaceError(std::string file, std::vector<SurfaceProblem> problems, std::vector<uint64_t> counts)
    : Error(describe(file, problems, counts)), file_(std::move(file)), problems_(std::move(problems)), counts_(std::move(counts)) {
  counts_.resize(kSurfaceProblemKinds, 0);
}

}  // namespace sweepcdt::io
