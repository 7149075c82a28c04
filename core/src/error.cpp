#include "sweepcdt/error.h"

namespace sweepcdt {

const char* to_string(PlcProblemKind kind) {
  switch (kind) {
    case PlcProblemKind::BadShape: return "bad-shape";
    case PlcProblemKind::NonFinitePoint: return "non-finite-point";
    case PlcProblemKind::IndexOutOfRange: return "index-out-of-range";
    case PlcProblemKind::RepeatedVertex: return "repeated-vertex";
    case PlcProblemKind::DuplicatePoints: return "duplicate-points";
    case PlcProblemKind::DegenerateSimplex: return "degenerate-simplex";
    case PlcProblemKind::DuplicateSimplex: return "duplicate-simplex";
    case PlcProblemKind::Intersection: return "intersection";
    case PlcProblemKind::PointOnSimplex: return "point-on-simplex";
    case PlcProblemKind::BadRegionSeed: return "bad-region-seed";
    case PlcProblemKind::LowerDimensional: return "lower-dimensional";
  }
  return "unknown";
}

namespace {
std::string describe(const std::vector<PlcProblem>& problems, uint64_t total) {
  std::string s = "invalid PLC: " + std::to_string(total) + " problem" + (total == 1 ? "" : "s");
  for (const auto& p : problems) s += "\n  " + p.message;
  if (total > problems.size()) s += "\n  ... and " + std::to_string(total - problems.size()) + " more";
  return s;
}
}  // namespace

PlcError::PlcError(std::vector<PlcProblem> problems, uint64_t total)
    : Error(describe(problems, total)), problems_(std::move(problems)), total_(total) {}

}  // namespace sweepcdt
