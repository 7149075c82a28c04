// Typed errors of sweepcdt. Library code reports every failure by throwing one of these — never by
// exit/abort, since it runs inside host applications (FreeCAD, MeshLab, Python).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweepcdt {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What is wrong with a PLC, naming the elements involved.
enum class PlcProblemKind {
  BadShape,           // array sizes are not multiples of the dimension / notations count mismatch
  NonFinitePoint,     // NaN or infinite coordinate (element: point)
  IndexOutOfRange,    // a simplex names a point that does not exist (element: simplex)
  RepeatedVertex,     // a simplex names the same point twice (element: simplex)
  DuplicatePoints,    // two points with exactly equal coordinates (elements: point, point)
  DegenerateSimplex,  // a constraining simplex's vertices are affinely dependent (element: simplex)
  DuplicateSimplex,   // two constraining simplices with the same vertices (elements: simplex, simplex)
  Intersection,       // two simplices meet other than in their shared face (elements: simplex, simplex)
  PointOnSimplex,     // a point lies on a simplex it is not a vertex of (elements: point, simplex)
  BadRegionSeed,      // non-finite region seed (element: seed)
  LowerDimensional,   // the points lie in one hyperplane: there is nothing D-dimensional to triangulate
};

const char* to_string(PlcProblemKind kind);

struct PlcProblem {
  PlcProblemKind kind;
  std::vector<uint64_t> elements;  // indices, as documented per kind
  std::string message;             // one line, names the elements
};

// check(plc) found problems; `problems` holds the first ones of each kind, `total` counts all.
class PlcError : public Error {
 public:
  PlcError(std::vector<PlcProblem> problems, uint64_t total);
  const std::vector<PlcProblem>& problems() const { return problems_; }
  uint64_t total() const { return total_; }

 private:
  std::vector<PlcProblem> problems_;
  uint64_t total_;
};

}  // namespace sweepcdt
