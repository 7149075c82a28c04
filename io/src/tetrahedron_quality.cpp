#include "sweepcdt/io/tetrahedron_quality.h"

#include <array>
#include <cmath>

namespace sweepcdt::io {
namespace {

using Vec = std::array<double, 3>;
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

}  // namespace

double radius_ratio(const VolumeMesh& mesh, uint32_t tet) {
  std::array<Vec, 4> p;
  for (int i = 0; i < 4; ++i) {
    const std::size_t v = mesh.tetrahedra[4 * std::size_t{tet} + i];
    p[i] = {mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]};
  }
  // Edge vectors from p3; six times the volume is |a · (b × c)|.
  const Vec a = sub(p[0], p[3]), b = sub(p[1], p[3]), c = sub(p[2], p[3]);
  const double six_volume = std::abs(dot(a, cross(b, c)));
  if (six_volume == 0) return 0;
  // r = 3V / (sum of face areas); R = |(|a|² b×c + |b|² c×a + |c|² a×b)| / (12 V).
  const double areas = (norm(cross(a, b)) + norm(cross(b, c)) + norm(cross(c, a)) + norm(cross(sub(p[1], p[0]), sub(p[2], p[0])))) / 2;
  const double r = six_volume / 2 / areas;
  const Vec bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  const double aa = dot(a, a), bb = dot(b, b), cc = dot(c, c);
  const Vec w{aa * bc[0] + bb * ca[0] + cc * ab[0], aa * bc[1] + bb * ca[1] + cc * ab[1], aa * bc[2] + bb * ca[2] + cc * ab[2]};
  const double R = norm(w) / (2 * six_volume);
  return 3 * r / R;
}

}  // namespace sweepcdt::io
