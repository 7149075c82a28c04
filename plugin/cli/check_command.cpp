#include "check_command.h"

#include <filesystem>
#include <ostream>

#include "args.h"
#include "errors.h"
#include "exit_codes.h"
#include "run_options.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/verify_mesh.h"
#include "sweepcdt/perturbation_order.h"
#include "usage.h"

namespace sweepcdt::cli {

namespace fs = std::filesystem;

int run_check(const std::vector<std::string>& words, std::ostream& out, std::ostream& err) {
  std::vector<std::string> files;
  bool quiet = false;
  double snap = 0;  // --snap TOL: the input as `mesh --snap TOL` read it
  FacetMode facets = mesh_defaults().facets;  // as `mesh` makes them
  try {
    ArgReader args(words);
    while (!args.done()) {
      if (args.flag("--help") || args.flag("-h")) {
        out << check_help();
        return kOk;
      }
      std::string value;
      if (args.flag("--quiet") || args.flag("-q")) quiet = true;
      else if (args.value("--snap", value)) snap = parse_snap(value);
      else if (read_facets_option(args, facets)) continue;
      else if (args.at_option()) throw UsageError("unknown option '" + args.peek() + "'");
      else files.push_back(args.take());
    }
    if (files.size() != 2) throw UsageError("check needs INPUT (the surface) and OUTPUT (the volume mesh)");
  } catch (const UsageError& e) {
    err << "sweepcdt: " << e.what() << "\n" << check_usage();
    return kUsage;
  }
  const std::string& input = files[0];
  const std::string& output = files[1];
  Plc<3> plc;
  io::VolumeMesh mesh;
  for (const std::string* file : {&input, &output}) {
    try {
      if (file == &input) plc = io::import_plc(input, snap, nullptr, /*for_cdt=*/false);
      else mesh = io::read_volume_mesh(output);
    } catch (...) {
      const Failure f = describe_current_exception(*file);
      err << "sweepcdt: " << f.message << "\n";
      if (!quiet)
        for (const auto& d : f.details) err << "  " << d << "\n";
      return f.code;
    }
  }

  const MeshVerification v = io::verify_mesh(plc, mesh, facets);
  const bool coplanar = facets == FacetMode::Coplanar;
  if (!quiet) {
    out << input << ": " << plc.num_simplices() << " triangles, " << plc.num_points() << " vertices\n"
        << output << ": " << mesh.num_tetrahedra() << " tetrahedra, " << mesh.num_points() << " vertices ("
        << v.steiner_points << " Steiner points";
    if (v.steiner_points)
      out << ", " << v.steiner_exactly_on << (coplanar ? " exactly in the plane of their facet" : " exactly on their input triangle")
          << ", the others rounded split points of its edges";
    out << ")\n";
  }
  if (!v.ok()) {
    err << "sweepcdt: " << output << " is not the CDT of " << input << ": " << v.total_problems << " problem"
        << (v.total_problems == 1 ? "" : "s") << "\n";
    for (const auto& p : v.problems) err << "  " << output << ": " << p << "\n";
    if (v.total_problems > v.problems.size()) err << "  ... and " << v.total_problems - v.problems.size() << " more\n";
    if (v.suggest_triangles)
      err << "  note: " << output << " is the CDT of the input triangles, each a facet of its own: it was made with\n"
          << "  --facets triangles; check it with --facets triangles\n";
    if (v.suggest_coplanar)
      err << "  note: " << output << " has the right boundary for a mesh made with --facets coplanar (edge-adjacent,\n"
          << "  exactly coplanar input triangles merged into polygons): check it with --facets coplanar\n";
    if (fs::path(output).extension() == ".inp")
      err << "  note: Abaqus .inp rounds coordinates that do not fit CalculiX's 20-character fields, so such a file\n"
             "  cannot be exactly the CDT of its input; write .mesh, .vtu, .msh or .node to check exactly\n";
    return kNotValid;
  }
  if (quiet) return kOk;
  out << "valid: input vertices identical; " << v.boundary_triangles << " boundary triangles on the "
      << (coplanar ? "input's " + std::to_string(v.facets) + " coplanar facets, tiling them;\n" : "input triangles, covering them;\n")
      << (!v.file_boundary ? "       (the file lists no boundary triangles);\n"
          : !v.file_tags   ? "       the file's boundary triangles are those, oriented outward (the format has no tags);\n"
          : coplanar       ? "       the file's boundary triangles are those, oriented outward, tagged with their facet's first triangle;\n"
                           : "       the file's boundary triangles are those, oriented outward, tagged with their input triangle;\n")
      << "       validate(): topology, orientation, constraints, domain, every interior facet locally Delaunay";
  if (v.perturbation_order > 0)
    out << "\n       under perturbation order " << v.perturbation_order << " (" << perturbation_order_name(v.perturbation_order)
        << "; the vertex-id order has no CDT here, paper §6)";
  out << "\n";
  return kOk;
}

}  // namespace sweepcdt::cli
