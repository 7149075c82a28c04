#include "usage.h"

namespace sweepcdt::cli {

std::string exit_codes_text() {
  return "exit codes:\n"
         "  0    success\n"
         "  1    internal error or out of memory\n"
         "  2    usage error (unknown option, missing argument)\n"
         "  3    unreadable or invalid input (malformed file, open or self-intersecting surface, invalid PLC)\n"
         "  4    no CDT exists for the input (with --steiner none; or Steiner points did not converge);\n"
         "       the message names witness vertices (0-based ids of the input's welded vertices)\n"
         "  5    an output could not be written (nothing is left under its name)\n"
         "  6    not a valid CDT (`check`, or `--check` refusing to write)\n"
         "  130  cancelled with Ctrl-C (nothing is written for the file in progress)\n"
         "  batch runs exit with the worst code of their files: 130 > 1 > 2 > 5 > 3 > 4 > 6 > 0\n";
}

std::string mesh_usage() {
  return "usage: sweepcdt INPUT -o OUTPUT [options]           (same as: sweepcdt mesh INPUT -o OUTPUT)\n"
         "       sweepcdt mesh INPUT... --out-dir DIR [--format F[,F...]] [--threads N] [options]\n";
}

std::string mesh_help() {
  return mesh_usage() +
         "\nTetrahedralize the interior of closed triangle surfaces (OFF, STL, OBJ, PLY, glTF/GLB, Draco .drc)\n"
         "into volume meshes: the constrained Delaunay tetrahedralization with the input triangles as faces.\n"
         "\n"
         "output:\n"
         "  -o, --output FILE   one input: the output file; its extension gives the format. Repeat it\n"
         "                      for several formats from one computation (-o a.mesh -o a.vtu)\n"
         "  --out-dir DIR       any number of inputs: DIR/<input stem>.<ext> each (DIR is created)\n"
         "  --format F[,F...]   mesh (Medit), vtu (VTK XML), msh (Gmsh 4.1), msh22 (Gmsh 2.2),\n"
         "                      tetgen (.node/.ele/.face), inp (Abaqus/CalculiX; coordinates that do not\n"
         "                      fit its 20-character fields are rounded, with a warning); default from\n"
         "                      -o's extension, mesh with --out-dir; a list (--format mesh,vtu) only\n"
         "                      with --out-dir\n"
         "  --threads N         convert N files at a time (output identical to one thread)\n"
         "computation:\n"
         "  --algorithm A       cavity-sweep (default: Delaunay, then the sweep where constraints are\n"
         "                      missing), sweep-sphere, sweep-plane, giftwrap (slow reference)\n"
         "  --steiner auto|none auto (default): add Steiner points on the surface where it has no CDT as\n"
         "                      given; none: the surface exactly, or exit 4 naming the obstruction\n"
         "                      (exactly cospherical vertices: up to 8 perturbation orders are tried);\n"
         "                      then each Steiner point is deleted again where a CDT exists without it\n"
         "  --keep-steiner-points  keep every Steiner point refinement added (no deletion pass)\n"
         "  --facets MODE       coplanar (default): edge-adjacent, exactly coplanar triangles form one\n"
         "                      polygonal facet, re-triangulated by its 2D CDT (CAD meshes fan long thin\n"
         "                      triangles across flat faces; face ids name each facet's first input\n"
         "                      triangle); triangles: every input triangle is a facet of its own (its\n"
         "                      index the face id; far more Steiner points on such meshes)\n"
         "  --snap TOL          repair CAD rounding noise first (off by default: the input is exact):\n"
         "                      along each axis, coordinates within TOL x the bounding-box diagonal\n"
         "                      of each other become one value (the most frequent), so faces flat by\n"
         "                      design (z = 0 stored as z = 5e-17) are exactly flat; 0 < TOL <= 1e-3,\n"
         "                      e.g. --snap 1e-12. Points that meet are merged; the\n"
         "                      summary and --stats say how many moved. `check` needs the same --snap\n"
         "  --check             verify the result exactly before writing, as `check` does; refuse (exit 6) if not valid\n"
         "reporting:\n"
         "  --stats FILE.json   counts, Steiner points, per-phase times, peak memory (written atomically)\n"
         "  -q, --quiet         only errors\n"
         "\n"
         "Progress: a bar on stderr when it is a terminal and a file takes over a second, log lines\n"
         "otherwise. Ctrl-C cancels cleanly (exit 130, no partial output). Outputs are written to a\n"
         "temporary file and renamed, so a failure never leaves a partial mesh under the output's name;\n"
         "an input that fails leaves none of its outputs. Messages go to stderr.\n"
         "\n" +
         exit_codes_text();
}

std::string check_usage() { return "usage: sweepcdt check INPUT OUTPUT [--facets triangles|coplanar] [--snap TOL] [--quiet]\n"; }

std::string check_help() {
  return check_usage() +
         "\nVerify that the volume mesh OUTPUT (any format `mesh` writes) is the constrained Delaunay\n"
         "tetrahedralization of the closed surface INPUT, exactly:\n"
         "  - OUTPUT's first vertices are INPUT's welded vertices, bit for bit, in order;\n"
         "  - every further vertex (a Steiner point) is exactly the construction `--steiner auto`\n"
         "    uses, a + t (b - a) rounded coordinate by coordinate for some t in (0, 1), from two\n"
         "    neighbouring points on an edge of a facet (vertices or earlier Steiner points; decided\n"
         "    exactly, no tolerance); so it lies on that edge up to the rounding of that arithmetic\n"
         "    (exactly, when it is exactly coplanar with its facet; the report counts which); the few\n"
         "    points that split a fold inside a facet: the same from any two of its points;\n"
         "  - the boundary of the tetrahedra, split at the Steiner points, is made of pieces of the\n"
         "    facets, each with the input's inside on the same side, tiling each facet: every edge\n"
         "    inside it shared by two pieces, its boundary edges split at their points each in one,\n"
         "    every point on it a vertex;\n"
         "  - the file's boundary triangles (if it lists them) are exactly those, outward, tagged\n"
         "    with their face id (if the format stores tags);\n"
         "  - validate(): tetrahedra positively oriented and properly connected, the domain covered\n"
         "    exactly (volumes), every constraint present, every interior facet locally Delaunay\n"
         "    (without Steiner points: under the first of the perturbation orders mesh tries).\n"
         "\n"
         "  --facets MODE       the --facets the mesh was made with. coplanar (default, as `mesh`):\n"
         "                      edge-adjacent, exactly coplanar input triangles with the inside on one\n"
         "                      side form one polygonal facet, its face id its first triangle's index;\n"
         "                      triangles: each input triangle is a facet, its face id its index. A mesh\n"
         "                      made with triangles passes as coplanar too, but for its face ids\n"
         "  --snap TOL          the input as `mesh --snap TOL` snapped it (give the same TOL)\n"
         "  -q, --quiet         no report; problems only\n"
         "Exit 0: valid; 6: not valid (the first problems are printed); 3: INPUT or OUTPUT unreadable.\n"
         "\n" +
         exit_codes_text();
}

std::string cdt_usage() {
  return "usage: sweepcdt cdt FILE -o OUTPUT [--format F] [--algorithm A] [--steiner none|auto] [--check]\n"
         "                   [--delete IDS] [--stats FILE.json] [--quiet]\n";
}

std::string cdt_help() {
  return cdt_usage() +
         "\nThe CDT of a piecewise linear complex in any dimension 2..5: Triangle .poly (2D), TetGen .poly or\n"
         ".smesh (3D), sweepcdt .plc (any dimension; see io/README.md).\n"
         "  -o, --output FILE   .node (.node/.ele: Triangle's in 2D, TetGen's in 3D; --format tetgen adds .face),\n"
         "                      .simplices (any dimension), or in 3D any volume format of `mesh`\n"
         "  --format F          node, simplices, or (3D) mesh, vtu, msh, msh22, tetgen, inp\n"
         "  --steiner none|auto none (default): the PLC exactly; auto: Steiner points (3D only)\n"
         "  --check             validate() the result exactly once more before writing; refuse (exit 6)\n"
         "                      if not valid\n"
         "  --delete IDS        then delete these vertices (ids from 0 in FILE's order, e.g. 3,17,42) from\n"
         "                      the CDT and the PLC, one by one (paper §5): a vertex inside the domain or\n"
         "                      inside a facet (which is re-triangulated; in 3D also on a straight edge\n"
         "                      of one) goes when a CDT exists without it; the others stay, each with a\n"
         "                      warning saying why (simplices with different tags — Triangle segment\n"
         "                      markers, TetGen facet markers — are different facets, never merged).\n"
         "                      The output numbers the vertices left in their order\n"
         "  --algorithm, --stats, --quiet   as for `mesh`\n"
         "\n" +
         exit_codes_text();
}

std::string info_usage() { return "usage: sweepcdt info INPUT [--json]\n"; }

std::string info_help() {
  return info_usage() +
         "\nWhat the importer sees in a surface file (OFF, STL, OBJ, PLY, glTF/GLB, Draco): counts, welding,\n"
         "closed, manifold, orientation, shells and nesting, self-intersections.\n"
         "exit codes: 0 valid closed surface, 2 usage error, 3 unreadable or invalid input\n";
}

std::string general_usage() {
  return mesh_usage() +
         "       sweepcdt check INPUT OUTPUT [--facets triangles|coplanar] [--snap TOL]\n"
         "       sweepcdt cdt FILE -o OUTPUT\n"
         "       sweepcdt info INPUT [--json]\n"
         "       sweepcdt help [COMMAND] | --help | --version\n";
}

std::string general_help() {
  return "sweepcdt " SWEEPCDT_VERSION " - exact constrained Delaunay tetrahedralization of closed surfaces\n\n" + general_usage() +
         "\ncommands:\n"
         "  mesh    closed surfaces -> volume meshes (.mesh .vtu .msh .node .inp); the default command\n"
         "  check   verify that a volume mesh is the CDT of a surface\n"
         "  cdt     CDT of a PLC file in any dimension (.poly, .smesh, .plc)\n"
         "  info    what the importer sees in a surface file\n"
         "`sweepcdt help COMMAND` or `sweepcdt COMMAND --help` describes each command's options.\n"
         "\n" +
         exit_codes_text();
}

}  // namespace sweepcdt::cli
