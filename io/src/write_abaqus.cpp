// Abaqus / CalculiX .inp (ccx reads it as is).
//   *NODE, NSET=NALL                      id, x, y, z                    (ids 1..n)
//   *ELEMENT, TYPE=C3D4, ELSET=REGION<k>  id, n1, n2, n3, n4             (one block per region k = r+1;
//                                                                         ids 1..t in mesh order)
//   *NSET, NSET=NBOUNDARY                 the nodes of the boundary triangles
//   *SURFACE, NAME=BOUNDARY, TYPE=ELEMENT element, S<face>            (the boundary as element faces)
// Boundary tags have no place here (a surface per input triangle would be useless): they are lost.
//
// Coordinates: CalculiX reads at most 20 characters per field, and the shortest exact text of a double
// can take 24 ("-2.2250738585072014e-308"). Each coordinate is written exactly in the shortest of
// several equivalent spellings (exponent without padding, mantissa without its point); only when
// none fits in 20 characters is it rounded to the nearest decimal with fewer digits (at least 14:
// "-" + 14 digits + "e-308"; relative change below 5e-15). Such coordinates are rare: they need
// 16-17 significant digits, a sign and an exponent, like float noise near zero (-1.7347234759768071e-16).
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <map>

#include "facet_keys.h"
#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

// Abaqus/CalculiX C3D4 faces: S1 = (1 2 3), S2 = (1 4 2), S3 = (2 4 3), S4 = (3 4 1). The file order
// is (v0, v1, v3, v2), so the face without sweepcdt's vertex i is:
constexpr int kFaceWithout[4] = {3, 4, 1, 2};

void list(std::string& out, const std::vector<int64_t>& ids) {
  for (std::size_t i = 0; i < ids.size(); ++i) {  // at most 16 entries per data line
    append_int(out, ids[i]);
    out += (i + 1) % 16 == 0 || i + 1 == ids.size() ? "\n" : ", ";
  }
}

// "e-08" -> "e-8", "e+20" -> "e20".
std::string compact_exponent(std::string s) {
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  const bool negative = !exponent.empty() && exponent[0] == '-';
  if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) exponent.erase(0, 1);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

// "d.ddde-N" -> "dddde-M" (no decimal point).
std::string without_point(const std::string& s) {
  const std::size_t e = s.find('e'), dot = s.find('.');
  if (e == std::string::npos || dot == std::string::npos || dot > e) return s;
  const long exponent = std::strtol(s.c_str() + e + 1, nullptr, 10) - static_cast<long>(e - dot - 1);
  return s.substr(0, dot) + s.substr(dot + 1, e - dot - 1) + "e" + std::to_string(exponent);
}

std::string text(double x, std::chars_format format, int precision = -1) {
  char buf[64];
  const auto r = precision < 0 ? std::to_chars(buf, buf + sizeof buf, x, format) : std::to_chars(buf, buf + sizeof buf, x, format, precision);
  return std::string(buf, r.ptr);
}

constexpr std::size_t kCalculixField = 20;

std::string calculix_number(double x) {
  std::string best = text(x, std::chars_format::general);
  for (const std::string& candidate : {compact_exponent(text(x, std::chars_format::scientific)),
                                       without_point(compact_exponent(text(x, std::chars_format::scientific)))})
    if (candidate.size() < best.size()) best = candidate;
  for (int digits = 16; best.size() > kCalculixField && digits > 0; --digits)  // rounded: see above
    best = without_point(compact_exponent(text(x, std::chars_format::scientific, digits - 1)));
  return best;
}

}  // namespace

int abaqus_face_without(int i) { return kFaceWithout[i]; }

void abaqus_text(const VolumeMesh& m, TextOut& o) {
  std::string& out = o.text;
  out += "*HEADING\nsweepcdt volume mesh: C3D4 tetrahedra, ELSET REGION<k> per region, SURFACE BOUNDARY\n*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < m.num_points(); ++i) {
    append_int(out, static_cast<int64_t>(i) + 1);
    for (int k = 0; k < 3; ++k) out += ", " + calculix_number(m.points[3 * i + k]);
    out += '\n';
    o.spill();
  }
  std::map<int32_t, std::vector<std::size_t>> regions;
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) regions[m.regions[t]].push_back(t);
  for (const auto& [r, tets] : regions) {
    out += "*ELEMENT, TYPE=C3D4, ELSET=REGION" + std::to_string(int64_t{r} + 1) + "\n";
    for (std::size_t t : tets) {
      append_int(out, static_cast<int64_t>(t) + 1);
      for (uint32_t v : file_order(&m.tetrahedra[4 * t])) {
        out += ", ";
        append_int(out, int64_t{v} + 1);
      }
      out += '\n';
      o.spill();
    }
  }
  if (m.num_boundary() == 0) return;

  std::vector<int64_t> nodes(m.boundary.begin(), m.boundary.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  for (auto& v : nodes) ++v;
  out += "*NSET, NSET=NBOUNDARY\n";
  list(out, nodes);

  // Each boundary triangle as the face of the one tetrahedron it bounds.
  std::map<std::array<uint32_t, 3>, std::pair<std::size_t, int>> faces;
  for (std::size_t b = 0; b < m.num_boundary(); ++b) faces[TriangleKeys::key(&m.boundary[3 * b])] = {kNone, 0};
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t)
    for (int i = 0; i < 4; ++i) {
      const auto f = outward_facet(&m.tetrahedra[4 * t], i);
      const auto it = faces.find(TriangleKeys::key(f.data()));
      if (it != faces.end()) it->second = {t, i};
    }
  out += "*SURFACE, NAME=BOUNDARY, TYPE=ELEMENT\n";
  for (std::size_t b = 0; b < m.num_boundary(); ++b) {
    const auto [t, i] = faces.at(TriangleKeys::key(&m.boundary[3 * b]));
    if (t == kNone) continue;  // a triangle that bounds no tetrahedron is no element face
    append_int(out, static_cast<int64_t>(t) + 1);
    out += ", S" + std::to_string(kFaceWithout[i]) + "\n";
    o.spill();
  }
}

}  // namespace sweepcdt::io::detail
