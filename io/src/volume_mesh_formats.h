// The per-format volume-mesh writers and readers behind write_volume_mesh() / read_volume_mesh(),
// and the conventions they share.
//
// Orientation. VolumeMesh stores tetrahedra positive in sweepcdt's convention,
// orient(a, b, c, d) = sign det [a-d; b-d; c-d] > 0 (Shewchuk's orient3d), which is the NEGATIVE of
// the convention of every file format here (VTK, Gmsh, Medit, TetGen, Abaqus/CalculiX all want
// det [b-a; c-a; d-a] > 0). So files hold (a, b, d, c): the last two swapped, both ways.
//
// Ids in files. Points and elements are 1-based where the format numbers them (0-based in .vtu,
// which has no numbers). Region r is written as r + 1 and boundary tag g as g + 1, so that 0 always
// means "none" (Gmsh forbids physical tag 0, Medit uses ref 0 for "no reference").
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "file_io.h"
#include "reader_util.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::io::detail {

// A tetrahedron in file order (standard positive volume) from one in VolumeMesh order, and back
// (the same swap).
inline std::array<uint32_t, 4> file_order(const uint32_t* t) { return {t[0], t[1], t[3], t[2]}; }

// Facet i (the one without vertex i) of a tetrahedron positive in sweepcdt's convention, ordered
// counterclockwise seen from outside the tetrahedron. Facet 3 (v0, v1, v2) has v3 on its positive
// side, the inside; replacing v_i by v3 makes an odd permutation, so the other facets are reversed.
inline std::array<uint32_t, 3> outward_facet(const uint32_t* t, int i) {
  if (i == 3) return {t[0], t[1], t[2]};
  std::array<uint32_t, 3> f{};
  int k = 0;
  for (int j = 0; j < 3; ++j) f[k++] = j == i ? t[3] : t[j];
  return {f[1], f[0], f[2]};
}

// Checks the mesh's internal consistency before writing (sizes, ids < number of points, region and
// tag ranges), so a writer never emits a file its own reader refuses. Throws InputError (Unsupported).
void check_writable(const VolumeMesh& mesh, const std::string& file);

// Writers: the text of the file(s), made piece by piece into `out` (file_io.h: a large mesh's file is
// written as it is made), or whole as one string.
void medit_text(const VolumeMesh& mesh, TextOut& out);
void vtu_text(const VolumeMesh& mesh, TextOut& out);
void gmsh_text(const VolumeMesh& mesh, bool version2, TextOut& out);
void abaqus_text(const VolumeMesh& mesh, TextOut& out);
void tetgen_node_text(const VolumeMesh& mesh, TextOut& out);
void tetgen_ele_text(const VolumeMesh& mesh, TextOut& out);
void tetgen_face_text(const VolumeMesh& mesh, TextOut& out);
template <class... Args>
std::string whole_text(const VolumeMesh& mesh, void (*writer)(const VolumeMesh&, Args..., TextOut&), Args... args) {
  TextOut out;
  writer(mesh, args..., out);
  return std::move(out.text);
}
inline std::string medit_text(const VolumeMesh& mesh) { return whole_text(mesh, medit_text); }
inline std::string vtu_text(const VolumeMesh& mesh) { return whole_text(mesh, vtu_text); }
inline std::string gmsh_text(const VolumeMesh& mesh, bool version2) { return whole_text<bool>(mesh, gmsh_text, version2); }
inline std::string abaqus_text(const VolumeMesh& mesh) { return whole_text(mesh, abaqus_text); }
// The C3D4 face number (1..4) of the facet without vertex i (sweepcdt order).
int abaqus_face_without(int i);
struct TetGenFiles {
  std::string node, ele, face;
};
TetGenFiles tetgen_texts(const VolumeMesh& mesh);

// Readers of the bytes of one file; TetGen's reads its files by name (the .face may be absent).
VolumeMesh read_medit(std::string_view bytes, const std::string& file);
VolumeMesh read_vtu(std::string_view bytes, const std::string& file);
VolumeMesh read_gmsh(std::string_view bytes, const std::string& file);
VolumeMesh read_abaqus(std::string_view bytes, const std::string& file);
VolumeMesh read_tetgen(const std::filesystem::path& node, const std::filesystem::path& ele, const std::filesystem::path& face);

// The three names of a TetGen mesh given any of them (or the stem).
struct TetGenNames {
  std::filesystem::path node, ele, face;
};
TetGenNames tetgen_names(const std::filesystem::path& file);

// Final consistency of a mesh read from `file`: every id in range. Throws InputError (IndexOutOfRange).
void check_read(const VolumeMesh& mesh, const std::string& file);

}  // namespace sweepcdt::io::detail

namespace sweepcdt::io::detail {

// A boundary tag as written (0 = none) and back.
inline int64_t file_tag(uint32_t tag) { return tag == kNone ? 0 : int64_t{tag} + 1; }
inline uint32_t tag_from_file(int64_t written) { return written == 0 ? kNone : static_cast<uint32_t>(written - 1); }
// A point's reference or marker as VolumeMesh::on_triangle: sweepcdt writes 0 or triangle + 1; what
// other tools write there (any integer) is no triangle.
inline uint32_t triangle_from_file(int64_t written) { return written >= 1 && written <= INT64_C(0xFFFFFFFF) ? static_cast<uint32_t>(written - 1) : kNone; }
// VolumeMesh::on_triangle[i], or kNone when the mesh does not say.
inline uint32_t point_triangle(const VolumeMesh& m, std::size_t i) { return i < m.on_triangle.size() ? m.on_triangle[i] : kNone; }

// The mesh's coordinates as "x y z" with the shortest exact text.
inline void append_point(std::string& out, const VolumeMesh& m, std::size_t i, char separator = ' ') {
  append_double(out, m.points[3 * i]);
  out += separator;
  append_double(out, m.points[3 * i + 1]);
  out += separator;
  append_double(out, m.points[3 * i + 2]);
}

}  // namespace sweepcdt::io::detail

namespace sweepcdt::io::detail {

// A count read from a text file: AbsurdCount if the bytes left cannot hold that many items of at
// least `min_bytes_each` bytes; returns the count.
inline uint64_t read_count(TextScanner& in, const char* what, uint64_t min_bytes_each) {
  const auto count = static_cast<uint64_t>(in.to_integer(in.next_token(), what, 0, INT64_MAX));
  if (count > in.bytes_left() / min_bytes_each)
    in.fail(InputErrorKind::AbsurdCount, std::to_string(count) + " " + what + " announced, but only " +
                                             std::to_string(in.bytes_left()) + " bytes follow");
  return count;
}

// A point id as written with first id `base` (0 or 1), checked against n points; 0-based.
inline uint32_t read_id(TextScanner& in, uint64_t n, int64_t base, const char* what) {
  const int64_t v = in.to_integer(in.next_token(), what);
  if (v < base || v - base >= static_cast<int64_t>(n))
    in.fail(InputErrorKind::IndexOutOfRange, std::string(what) + " " + std::to_string(v) + " does not exist (" +
                                                 std::to_string(n) + " points, numbered from " + std::to_string(base) + ")");
  return static_cast<uint32_t>(v - base);
}

// A region as written (r + 1 >= 1; 0 read as region 0 too, for files from elsewhere) to 0-based.
inline int32_t region_from_file(const TextScanner& in, int64_t written) {
  if (written < 0 || written > INT32_MAX) in.fail(InputErrorKind::Syntax, "region " + std::to_string(written) + " is outside [0, 2^31 - 1]");
  return written == 0 ? 0 : static_cast<int32_t>(written - 1);
}

}  // namespace sweepcdt::io::detail
