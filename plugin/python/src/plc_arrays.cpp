#include "plc_arrays.h"

#include <string>

#include "arrays.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::python {
namespace {

ExteriorSide exterior_side(int64_t v, std::size_t j) {
  if (v == 0) return ExteriorSide::None;
  if (v == 1) return ExteriorSide::Positive;
  if (v == -1) return ExteriorSide::Negative;
  throw py::value_error("exterior[" + std::to_string(j) + "] must be -1 (negative side exterior), 0 (none) or "
                        "1 (positive side exterior), not " + std::to_string(v));
}

}  // namespace

PlcArrays plc_arrays(const py::handle& points, const py::handle& simplices, const py::handle& exterior,
                     const py::handle& tags, const char* simplices_name) {
  PlcArrays a;
  a.simplices_name = simplices_name;
  a.points = real_matrix(points, "points", -1, &a.dimension);
  if (a.dimension < 2 || a.dimension > 5)
    throw py::value_error("points must have 2 to 5 columns (the dimension), not " + std::to_string(a.dimension));
  a.simplices = index_matrix(simplices, simplices_name, a.dimension);
  const std::size_t m = a.simplices.size() / a.dimension;
  if (!exterior.is_none()) a.exterior = index_vector(exterior, "exterior", m);
  if (!tags.is_none()) a.tags = index_vector(tags, "tags", m);
  for (std::size_t j = 0; j < a.tags.size(); ++j)
    if (a.tags[j] < 0 || a.tags[j] >= static_cast<int64_t>(kNone)) throw py::value_error("tags[" + std::to_string(j) + "] must be in [0, 2^32 - 1)");
  return a;
}

template <int D>
Plc<D> plc_of(PlcArrays a) {
  Plc<D> plc;
  plc.points = std::move(a.points);
  const std::size_t n = plc.num_points();
  plc.simplices.reserve(a.simplices.size());
  for (std::size_t c = 0; c < a.simplices.size(); ++c) {
    if (a.simplices[c] < 0 || a.simplices[c] >= static_cast<int64_t>(kNone))
      throw py::value_error(std::string(a.simplices_name) + "[" + std::to_string(c / D) + "]: point id " + std::to_string(a.simplices[c]) +
                            " is not in [0, " + std::to_string(n) + ")");
    plc.simplices.push_back(static_cast<uint32_t>(a.simplices[c]));
  }
  for (std::size_t j = 0; j < a.exterior.size(); ++j) plc.exterior.push_back(exterior_side(a.exterior[j], j));
  for (int64_t t : a.tags) plc.tags.push_back(static_cast<uint32_t>(t));
  return plc;
}

int64_t exterior_code(ExteriorSide side) {
  return side == ExteriorSide::Negative ? -1 : side == ExteriorSide::Positive ? 1 : 0;
}

template Plc<2> plc_of<2>(PlcArrays);
template Plc<3> plc_of<3>(PlcArrays);
template Plc<4> plc_of<4>(PlcArrays);
template Plc<5> plc_of<5>(PlcArrays);

}  // namespace sweepcdt::python
