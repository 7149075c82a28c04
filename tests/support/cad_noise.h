// CAD rounding noise, as CAD exports carry it (issue 13): coordinates that are flat or on a plane by
// design, stored a few units in the last place off (pipe_tee_fine.stl: z = -2.7e-15 for 0). Added
// to clean parts so that tests meet the noise that real exports have and the committed parts lack.
#pragma once
#include <cmath>
#include <cstdint>

#include <vector>

#include "sweepcdt/plc.h"
#include "test_shapes.h"

namespace sweepcdt::testing {

// Each coordinate of `plc`'s points, with probability `fraction`, moves by 1 to 4 units in the last
// place (a zero by 1 to 4 times 5e-17), up or down; deterministic in `seed` (splitmix64).
inline Plc<3> with_cad_noise(Plc<3> plc, double fraction, uint64_t seed) {
  uint64_t state = seed;
  const auto next = [&state] {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  for (double& x : plc.points) {
    const uint64_t r = next();
    if (static_cast<double>(r >> 11) * 0x1p-53 >= fraction) continue;
    const double units = static_cast<double>(1 + (r & 3)) * ((r & 4) ? 1 : -1);
    x += x == 0 ? units * 5e-17 : units * (std::nextafter(std::abs(x), INFINITY) - std::abs(x));
  }
  return plc;
}

// `fins` thin fins (fixtures::extruded_columns) with CAD noise on half the coordinates: Steiner
// points made from their segments' ends and from pieces, folds, points rounded off their segments,
// and a refined PLC whose bent facets miss many Delaunay faces (the cavity sweep's cavities). `seed`
// picks the noise.
inline Plc<3> noisy_fins(uint64_t seed = 7, int fins = 4) {
  std::vector<double> xs{0, 1}, tops{0.2};
  for (int fin = 0; fin < fins; ++fin) {
    xs.push_back(xs.back() + 0.02);
    tops.push_back(1.0);
    xs.push_back(xs.back() + 0.2);
    tops.push_back(0.2 + 0.01 * fin);
  }
  return with_cad_noise(fixtures::extruded_columns(xs, tops, 1.0), 0.5, seed);
}

}  // namespace sweepcdt::testing
