// Volume-mesh export (issue 6): volume_mesh_of() checked exactly, then every format written and read
// back by our own reader (exact comparison) and by independent programs: meshio (all formats; signed
// volumes recomputed in numpy), gmsh (Jacobians of .msh and .mesh), ccx (a static analysis of the .inp)
// and tetgen -rC (consistency of .node/.ele/.face).
#include <gtest/gtest.h>

#include <set>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "external_tools.h"
#include "io_test_util.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/volume_mesh.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io {
namespace {

using testing::quoted;
using testing::run_tool;
using testing::TempDir;

// Small valid meshes of ../shared/data that get a CDT with Steiner points (the others are listed in
// tests/integration/shared_meshes_cdt_test.cpp; larger ones only make the run slower). Box, cubevc and
// cube_att get Steiner points, two_objects two regions.
const char* kMeshes[] = {"off/icosahedron.off", "gltf/Box.gltf", "gltf/two_objects_inverse_materials.gltf", "glb/cubevc.glb",
                         "drc/cube_att.drc"};

struct Case {
  std::string name;
  Plc<3> input;
  VolumeMesh mesh;
  mpq_class six_volume;  // 6 x the exact volume enclosed by the input surface
};

mpq_class q(double x) { return mpq_class(x); }

// 6 x signed volume of (a, b, c, d), standard orientation det [b-a; c-a; d-a], exactly.
mpq_class six_volume(const double* a, const double* b, const double* c, const double* d) {
  mpq_class m[3][3];
  for (int k = 0; k < 3; ++k) {
    m[0][k] = q(b[k]) - q(a[k]);
    m[1][k] = q(c[k]) - q(a[k]);
    m[2][k] = q(d[k]) - q(a[k]);
  }
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

const double kOrigin[3] = {0, 0, 0};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    std::vector<Case> out;
    const std::filesystem::path data(SWEEPCDT_SHARED_DATA);
    for (const char* name : kMeshes) {
      if (!std::filesystem::exists(data / name)) {
        ADD_FAILURE() << "missing shared mesh " << data / name;
        continue;
      }
      Case c{name, import_plc(data / name), {}, 0};
      Options options;
      options.steiner = SteinerMode::Auto;
      Plc<3> triangulated;
      const Triangulation<3> tri = cdt(c.input, options, &triangulated);
      c.mesh = volume_mesh_of(tri, triangulated);
      for (std::size_t j = 0; j < c.input.num_simplices(); ++j) {
        const uint32_t* f = c.input.simplex(j);
        const bool outward = c.input.exterior[j] == ExteriorSide::Negative;  // counterclockwise from outside
        c.six_volume += six_volume(kOrigin, c.input.point(f[0]), c.input.point(outward ? f[1] : f[2]), c.input.point(outward ? f[2] : f[1]));
      }
      out.push_back(std::move(c));
    }
    return out;
  }();
  return all;
}

bool have_cases() {
  if (!std::filesystem::exists(SWEEPCDT_SHARED_DATA)) return false;
  return !cases().empty();
}

TEST(VolumeMeshOf, ExactVolumesOrientationAndBoundary) {
  if (!have_cases()) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  bool some_steiner = false, some_regions = false;
  for (const Case& c : cases()) {
    const VolumeMesh& m = c.mesh;
    SCOPED_TRACE(c.name);
    ASSERT_EQ(m.regions.size(), m.num_tetrahedra());
    ASSERT_EQ(m.boundary_tags.size(), m.num_boundary());
    EXPECT_EQ(m.num_input_points, c.input.num_points());
    some_steiner |= m.num_points() > m.num_input_points;
    some_regions |= *std::max_element(m.regions.begin(), m.regions.end()) > 0;
    mpq_class tets = 0, boundary = 0;
    for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
      const uint32_t* v = &m.tetrahedra[4 * t];
      auto p = [&](int k) { return &m.points[3 * std::size_t{v[k]}]; };
      // sweepcdt's orient > 0 ...
      ASSERT_EQ(predicates::orient<3>({p(0), p(1), p(2), p(3)}), predicates::Sign::Positive) << "tetrahedron " << t;
      // ... is a negative standard volume: the files swap two vertices.
      const mpq_class v6 = six_volume(p(0), p(1), p(2), p(3));
      ASSERT_LT(v6, 0) << "tetrahedron " << t;
      tets -= v6;
    }
    for (std::size_t b = 0; b < m.num_boundary(); ++b) {
      const uint32_t* f = &m.boundary[3 * b];
      boundary += six_volume(kOrigin, &m.points[3 * std::size_t{f[0]}], &m.points[3 * std::size_t{f[1]}], &m.points[3 * std::size_t{f[2]}]);
      ASSERT_LT(m.boundary_tags[b], c.input.num_simplices()) << "boundary triangle " << b << " has no input triangle";
      // Each boundary triangle lies in the plane of its input triangle (Steiner points only to within
      // rounding: sweepcdt/steiner_point.h).
      const uint32_t* g = c.input.simplex(m.boundary_tags[b]);
      for (int k = 0; k < 3; ++k)
        if (f[k] < m.num_input_points) EXPECT_EQ(predicates::orient<3>({c.input.point(g[0]), c.input.point(g[1]), c.input.point(g[2]), &m.points[3 * std::size_t{f[k]}]}),
                  predicates::Sign::Zero);
    }
    // Each Steiner point names an input triangle it lies on: a boundary piece of that triangle has it
    // as a corner (input vertices name none).
    ASSERT_EQ(m.on_triangle.size(), m.num_points());
    std::set<std::pair<uint32_t, uint32_t>> corner_of;  // (point, tag of a boundary triangle at it)
    for (std::size_t b = 0; b < m.num_boundary(); ++b)
      for (int k = 0; k < 3; ++k) corner_of.insert({m.boundary[3 * b + k], m.boundary_tags[b]});
    for (uint32_t i = 0; i < m.num_points(); ++i)
      if (i < m.num_input_points) EXPECT_EQ(m.on_triangle[i], kNone) << i;
      else EXPECT_TRUE(corner_of.count({i, m.on_triangle[i]})) << "Steiner point " << i << " on input triangle " << m.on_triangle[i];
    // The boundary triangles, counterclockwise seen from outside, enclose exactly the volume of the
    // tetrahedra (divergence theorem, exact rationals); that is the volume the input surface encloses,
    // exactly without Steiner points, to within their rounding with them.
    EXPECT_EQ(boundary, tets);
    if (m.num_points() == m.num_input_points) EXPECT_EQ(tets, c.six_volume);
    EXPECT_LE(mpq_class(abs(tets - c.six_volume)).get_d(), 1e-12 * c.six_volume.get_d());
    std::printf("  %-42s %6zu points (%zu Steiner) %7zu tetrahedra %6zu boundary triangles\n", c.name.c_str(), m.num_points(),
                m.num_points() - m.num_input_points, m.num_tetrahedra(), m.num_boundary());
  }
  EXPECT_TRUE(some_steiner) << "no case has Steiner points: the Steiner-point paths are untested";
  EXPECT_TRUE(some_regions) << "no case has two regions";
}

struct FormatCase {
  MeshFormat format;
  const char* file;       // name written
  const char* meshio;     // meshio's file_format
  bool boundary_tags;     // the format keeps them
  bool steiner_flags;     // the format keeps num_input_points
  bool on_triangle;       // the format keeps each Steiner point's input triangle
};
const FormatCase kFormats[] = {
    {MeshFormat::Medit, "out.mesh", "medit", true, false, true},    {MeshFormat::Vtu, "out.vtu", "vtu", true, true, true},
    {MeshFormat::Gmsh41, "out.msh", "gmsh", true, false, false},    {MeshFormat::Gmsh22, "out22.msh", "gmsh", true, false, false},
    {MeshFormat::TetGen, "out.node", "tetgen", true, false, true},  {MeshFormat::Abaqus, "out.inp", "abaqus", false, false, false},
};

// Boundary triangles as a sorted list, each rotated to start at its smallest id (same orientation).
std::vector<std::array<uint32_t, 4>> canonical_boundary(const VolumeMesh& m, bool with_tags) {
  std::vector<std::array<uint32_t, 4>> out;
  for (std::size_t b = 0; b < m.num_boundary(); ++b) {
    const uint32_t* f = &m.boundary[3 * b];
    const int r = static_cast<int>(std::min_element(f, f + 3) - f);
    out.push_back({f[r], f[(r + 1) % 3], f[(r + 2) % 3], with_tags ? m.boundary_tags[b] : 0});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(VolumeMeshFiles, OwnReaderReadsBackExactly) {
  if (!have_cases()) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  TempDir dir;
  for (const Case& c : cases())
    for (const FormatCase& f : kFormats) {
      SCOPED_TRACE(c.name + " as " + to_string(f.format));
      const auto file = dir.path() / f.file;
      write_volume_mesh(file, c.mesh, f.format);
      const VolumeMesh back = read_volume_mesh(file);
      // Coordinates are the same doubles (shortest round-trip text; .inp: see write_abaqus.cpp), ids
      // and order unchanged.
      if (f.format != MeshFormat::Abaqus) {
        EXPECT_EQ(back.points, c.mesh.points);
      } else {
        ASSERT_EQ(back.points.size(), c.mesh.points.size());
        for (std::size_t i = 0; i < back.points.size(); ++i) EXPECT_NEAR(back.points[i], c.mesh.points[i], 5e-15 * std::abs(c.mesh.points[i])) << i;
      }
      EXPECT_EQ(back.tetrahedra, c.mesh.tetrahedra);
      EXPECT_EQ(back.regions, c.mesh.regions);
      if (f.boundary_tags) {
        EXPECT_EQ(back.boundary, c.mesh.boundary);
        EXPECT_EQ(back.boundary_tags, c.mesh.boundary_tags);
      } else {
        EXPECT_EQ(canonical_boundary(back, false), canonical_boundary(c.mesh, false));
      }
      EXPECT_EQ(back.num_input_points, f.steiner_flags ? c.mesh.num_input_points : c.mesh.num_points());
      EXPECT_EQ(back.on_triangle, f.on_triangle ? c.mesh.on_triangle : std::vector<uint32_t>{});
    }
}

// meshio (python3-meshio) reads the file; numpy recomputes every signed volume and the volume the
// boundary triangles enclose.
const char* kMeshioScript = R"PY(
import sys, meshio, numpy as np
for path, fmt in zip(sys.argv[1::2], sys.argv[2::2]):  # one interpreter for every file: meshio loads slowly
    m = meshio.read(path, file_format=fmt)
    P = np.asarray(m.points, dtype=float)
    T = np.concatenate([c.data for c in m.cells if c.type == "tetra"] or [np.zeros((0, 4), int)])
    F = np.concatenate([c.data for c in m.cells if c.type == "triangle"] or [np.zeros((0, 3), int)])
    a, b, c, d = (P[T[:, k]] for k in range(4))
    vol = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6
    bvol = np.einsum("ij,ij->i", P[F[:, 0]], np.cross(P[F[:, 1]], P[F[:, 2]])).sum() / 6
    regions = {}
    for key in ("region", "medit:ref", "gmsh:physical", "tetgen:ref"):
        if key in m.cell_data:
            for blk, data in zip(m.cells, m.cell_data[key]):
                if blk.type == "tetra":
                    for r in np.asarray(data).ravel():
                        regions[int(r)] = regions.get(int(r), 0) + 1
            break
    else:
        for name, sets in m.cell_sets.items():
            if name.upper().startswith("REGION"):
                regions[int(name[6:])] = sum(len(s) for s, blk in zip(sets, m.cells) if blk.type == "tetra")
    print("file", path, "points", len(P), "tetra", len(T), "triangles", len(F), "minvol", repr(float(vol.min())),
          "volume", repr(float(vol.sum())), "bvolume", repr(float(bvol)),
          "regions", ",".join("%d:%d" % kv for kv in sorted(regions.items())), flush=True)
)PY";

// The "key value" pairs of the script's line about `file`.
std::map<std::string, std::string> words(const std::string& output, const std::filesystem::path& file) {
  std::map<std::string, std::string> out;
  const auto at = output.find("file " + file.string() + " ");
  if (at == std::string::npos) return out;
  std::istringstream in(output.substr(at, output.find('\n', at) - at));
  std::string key, value;
  while (in >> key >> value) out[key] = value;
  return out;
}

std::string region_counts(const VolumeMesh& m) {
  std::map<int64_t, int> counts;
  for (int32_t r : m.regions) ++counts[int64_t{r} + 1];
  std::string s;
  for (const auto& [r, k] : counts) s += (s.empty() ? "" : ",") + std::to_string(r) + ":" + std::to_string(k);
  return s;
}

TEST(VolumeMeshFiles, MeshioReadsEveryFormat) {
  if (!have_cases()) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  if (!testing::require_meshio()) return;
  TempDir dir;
  const auto script = dir.write("check.py", kMeshioScript);
  std::string command = "/usr/bin/python3 " + quoted(script);
  auto file_of = [&](std::size_t k, const FormatCase& f) { return dir.path() / (std::to_string(k) + "_" + f.file); };
  for (std::size_t k = 0; k < cases().size(); ++k)
    for (const FormatCase& f : kFormats) {
      write_volume_mesh(file_of(k, f), cases()[k].mesh, f.format);
      command += " " + quoted(file_of(k, f)) + " " + f.meshio;
    }
  const auto run = run_tool(command);
  ASSERT_EQ(run.status, 0) << run.output;
  for (std::size_t k = 0; k < cases().size(); ++k)
    for (const FormatCase& f : kFormats) {
      const Case& c = cases()[k];
      SCOPED_TRACE(c.name + " as " + to_string(f.format));
      auto w = words(run.output, file_of(k, f));
      ASSERT_FALSE(w.empty()) << run.output;
      const double exact = c.six_volume.get_d() / 6;
      EXPECT_EQ(w["points"], std::to_string(c.mesh.num_points()));
      EXPECT_EQ(w["tetra"], std::to_string(c.mesh.num_tetrahedra()));
      EXPECT_GT(std::stod(w["minvol"]), 0) << "an inverted tetrahedron";
      EXPECT_NEAR(std::stod(w["volume"]), exact, 1e-12 * std::abs(exact));
      // .inp holds the boundary as element faces, not triangles; meshio's TetGen reader skips .face.
      if (f.format != MeshFormat::Abaqus && f.format != MeshFormat::TetGen) {
        EXPECT_EQ(w["triangles"], std::to_string(c.mesh.num_boundary()));
        EXPECT_NEAR(std::stod(w["bvolume"]), exact, 1e-12 * std::abs(exact)) << "boundary not outward";
      }
      EXPECT_EQ(w["regions"], region_counts(c.mesh));
    }
}

// gmsh loads .msh (4.1, 2.2) and .mesh and computes the Jacobian of every tetrahedron.
TEST(VolumeMeshFiles, GmshFindsNoNegativeJacobian) {
  if (!have_cases()) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  if (!testing::require_tool("gmsh", "gmsh")) return;
  TempDir dir;
  const auto geo = dir.write("quality.geo",
                             "Plugin(AnalyseMeshQuality).JacobianDeterminant = 1;\nPlugin(AnalyseMeshQuality).CreateView = 0;\n"
                             "Plugin(AnalyseMeshQuality).Run;\n");
  for (const Case& c : cases())
    for (const auto& [format, name] : {std::pair{MeshFormat::Gmsh41, "g.msh"}, {MeshFormat::Gmsh22, "g22.msh"}, {MeshFormat::Medit, "g.mesh"}}) {
      SCOPED_TRACE(c.name + " as " + to_string(format));
      const auto file = dir.path() / name;
      write_volume_mesh(file, c.mesh, format);
      const auto run = run_tool("timeout 120 gmsh -nt 1 " + quoted(file) + " " + quoted(geo) + " -");
      ASSERT_EQ(run.status, 0) << run.output;
      EXPECT_EQ(run.output.find("Error"), std::string::npos) << run.output;
      if (format != MeshFormat::Medit)  // gmsh's Medit reader does not print counts
        EXPECT_NE(run.output.find(std::to_string(c.mesh.num_tetrahedra() + c.mesh.num_boundary()) + " elements"), std::string::npos) << run.output;
      const auto at = run.output.find("minJ      =");
      ASSERT_NE(at, std::string::npos) << run.output;
      const double min_jacobian = std::stod(run.output.substr(at + 12));
      EXPECT_GT(min_jacobian, 0) << run.output;
    }
}

// CalculiX solves a static problem on the .inp: it stops with "nonpositive jacobian" on an inverted
// element, and needs the REGION element sets and the BOUNDARY surface to exist.
TEST(VolumeMeshFiles, CalculixSolvesOnTheInp) {
  if (!have_cases()) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  if (!testing::require_tool("ccx", "calculix-ccx")) return;
  TempDir dir;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    write_volume_mesh(dir.path() / "mesh.inp", c.mesh, MeshFormat::Abaqus);
    std::string job = "*INCLUDE, INPUT=mesh.inp\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n";
    std::map<int32_t, int> regions;
    for (int32_t r : c.mesh.regions) regions[r] = 1;
    for (const auto& [r, one] : regions) job += "*SOLID SECTION, ELSET=REGION" + std::to_string(r + 1) + ", MATERIAL=STEEL\n";
    // Three corners of every body held (each region is a separate body here), pressure on the boundary.
    job += "*BOUNDARY\n";
    for (const auto& [r, one] : regions) {
      const auto t = static_cast<std::size_t>(std::find(c.mesh.regions.begin(), c.mesh.regions.end(), r) - c.mesh.regions.begin());
      for (int k = 0; k < 3; ++k) job += std::to_string(c.mesh.tetrahedra[4 * t + k] + 1) + ", 1, 3\n";
    }
    job += "*STEP\n*STATIC\n*DSLOAD\nBOUNDARY, P, 1.0\n*NODE FILE\nU\n*END STEP\n";
    dir.write("job.inp", job);
    const auto run = run_tool("cd " + quoted(dir.path()) + " && timeout 300 ccx -i job");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(run.output.find("ERROR"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Job finished"), std::string::npos) << run.output;
  }
}

// tetgen -r rebuilds the mesh from .node/.ele/.face and -C checks its consistency. (tetgen -r reorients
// inverted tetrahedra silently, so orientation is checked by meshio above, not here.)
TEST(VolumeMeshFiles, TetgenReconstructsTheMesh) {
  if (!have_cases()) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  if (!testing::require_tool("tetgen", "tetgen")) return;
  TempDir dir;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    write_volume_mesh(dir.path() / "t", c.mesh, MeshFormat::TetGen);
    const auto run = run_tool("timeout 120 tetgen -rCNEF " + quoted(dir.path() / "t"));
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("Input tetrahedra: " + std::to_string(c.mesh.num_tetrahedra())), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Mesh tetrahedra: " + std::to_string(c.mesh.num_tetrahedra())), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("the mesh appears to be consistent"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Mesh boundaries connected correctly"), std::string::npos) << run.output;
  }
}

}  // namespace
}  // namespace sweepcdt::io
