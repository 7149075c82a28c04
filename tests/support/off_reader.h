// A minimal OFF reader for tests of the core (triangles only, no error recovery) until io/ has the
// real readers. Returns nothing when the file is missing, so tests can say so and skip.
#pragma once
#include <fstream>
#include <optional>
#include <string>

#include "sweepcdt/plc.h"

namespace sweepcdt::fixtures {

// The surface as a facet-bounded PLC, every triangle notated exterior Negative (counterclockwise
// from outside).
inline std::optional<Plc<3>> read_off_surface(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  Plc<3> plc;
  plc.points.resize(3 * nv);
  for (auto& x : plc.points) in >> x;
  for (std::size_t f = 0; f < nf; ++f) {
    std::size_t k = 0;
    in >> k;
    uint32_t a, b, c;
    in >> a >> b >> c;
    plc.simplices.insert(plc.simplices.end(), {a, b, c});
  }
  plc.exterior.assign(plc.num_simplices(), ExteriorSide::Negative);
  return plc;
}

}  // namespace sweepcdt::fixtures
