// The runtime dimension of the file is dispatched once, here (std::visit over io::AnyPlc), into
// cdt<D>; the output is Triangle/TetGen .node/.ele, sweepcdt .simplices, or in 3D a volume format.
#include "cdt_command.h"

#include <chrono>
#include <optional>
#include <ostream>
#include <variant>

#include "args.h"
#include "check_before_writing.h"
#include "convert_surface.h"
#include "errors.h"
#include "exit_codes.h"
#include "progress.h"
#include "report.h"
#include "stats.h"
#include "sweepcdt/editable_cdt.h"
#include "sweepcdt/io/plc_file.h"
#include "sweepcdt/io/volume_mesh.h"
#include "usage.h"

namespace sweepcdt::cli {
namespace {

namespace fs = std::filesystem;

// Either a plain triangulation format (any D) or a volume-mesh format (D = 3).
struct OutputFormat {
  std::optional<io::TriangulationFormat> plain;
  std::optional<io::MeshFormat> volume;
  std::string word;
};

std::optional<OutputFormat> format_named(const std::string& word) {
  if (word == "node" || word == "ele") return OutputFormat{io::TriangulationFormat::NodeEle, std::nullopt, "node"};
  if (word == "simplices") return OutputFormat{io::TriangulationFormat::Simplices, std::nullopt, "simplices"};
  if (const auto f = io::mesh_format_named(word)) return OutputFormat{std::nullopt, *f, io::to_string(*f)};
  return std::nullopt;
}

std::optional<OutputFormat> format_of(const std::string& file) {
  const std::string ext = fs::path(file).extension().string();
  if (ext == ".node" || ext == ".ele") return format_named("node");
  if (ext == ".simplices") return format_named("simplices");
  if (const auto f = io::mesh_format_of(file)) return OutputFormat{std::nullopt, *f, io::to_string(*f)};
  return std::nullopt;
}

// --delete: the listed vertices leave the CDT one by one (paper §5; sweepcdt/editable_cdt.h). A
// vertex that cannot go — no CDT without it, a corner of a facet, not a vertex — stays, with a
// warning saying why; the others go on.
// "3,17,42": vertex ids in the PLC file's order, from 0.
std::vector<uint32_t> parse_vertex_list(const std::string& text) {
  std::vector<uint32_t> ids;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string word = text.substr(at, comma - at);
    if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos || word.size() > 9)
      throw UsageError("--delete takes vertex ids separated by commas (e.g. 3,17,42), not '" + text + "'");
    ids.push_back(static_cast<uint32_t>(std::stoul(word)));
    at = comma + 1;
  }
  return ids;
}

template <int D>
void delete_vertices(Triangulation<D>& tri, Plc<D>& plc, const std::vector<uint32_t>& ids, FileResult& r) {
  EditableCdt<D> mesh(std::move(plc), std::move(tri));
  std::size_t deleted = 0;
  for (uint32_t v : ids) {
    try {
      mesh.remove_vertex(v);
      ++deleted;
    } catch (const Error& e) {
      r.warnings.push_back(r.input + ": vertex " + std::to_string(v) + " kept: " + e.what());
    }
  }
  r.warnings.push_back(r.input + ": " + std::to_string(deleted) + " of " + std::to_string(ids.size()) +
                       " vertices deleted (--delete; the output numbers the vertices left in their order)");
  auto snapshot = std::move(mesh).release();
  tri = std::move(snapshot.triangulation);
  plc = std::move(snapshot.plc);
}

template <int D>
void triangulate(const Plc<D>& plc, const std::string& output, const OutputFormat& format, const RunOptions& options,
                 const std::vector<uint32_t>& to_delete, FileProgress& progress, FileResult& r, bool& writing) {
  r.dimension = D;
  r.input_points = plc.num_points();
  r.input_simplices = plc.num_simplices();
  if (format.volume && D != 3)
    throw UsageError(output + ": " + format.word + " holds tetrahedra, but the PLC is " + std::to_string(D) + "-dimensional: use .node or .simplices");
  if (format.plain == io::TriangulationFormat::NodeEle && D > 3)
    throw UsageError(output + ": .node/.ele holds triangles (2D) or tetrahedra (3D), but the PLC is " + std::to_string(D) +
                     "-dimensional: use .simplices");
  if (options.steiner == SteinerMode::Auto && D != 3)
    throw UsageError("--steiner auto is for 3D PLCs; this one is " + std::to_string(D) + "-dimensional");
  const Options cdt_options = core_options(options, &r.cdt, progress.callback());
  Plc<D> triangulated;
  Triangulation<D> tri = cdt(plc, cdt_options, &triangulated);
  if (!to_delete.empty()) {
    for (uint32_t v : to_delete)
      if (v >= plc.num_points())
        throw UsageError("--delete: vertex " + std::to_string(v) + " does not exist (" + std::to_string(plc.num_points()) + " points, numbered from 0)");
    progress.phase("deleting vertices");
    delete_vertices(tri, triangulated, to_delete, r);
  }
  r.computed = true;
  r.simplices = tri.num_simplices();
  if (options.check && !check_before_writing(tri, triangulated, progress, r)) return;
  throw_if_interrupted();
  progress.phase("writing");
  const auto t = std::chrono::steady_clock::now();
  writing = true;
  if constexpr (D == 3) {
    if (format.volume) {
      const io::VolumeMesh mesh = counted_volume_mesh(std::move(tri), triangulated, r);
      io::write_volume_mesh(output, mesh, *format.volume);
      r.seconds_write = since(t);
      if (*format.volume == io::MeshFormat::Abaqus) warn_if_rounded(output, mesh, r);
      return;
    }
  }
  io::write_triangulation<D>(output, tri, *format.plain);
  r.seconds_write = since(t);
}

}  // namespace

int run_cdt(const std::vector<std::string>& words, std::ostream& out, std::ostream& err) {
  std::string input, output;
  std::optional<OutputFormat> format;
  RunOptions options;
  std::vector<uint32_t> to_delete;
  options.steiner = SteinerMode::None;  // a PLC is meant exactly as given; Steiner points on request
  options.facets = FacetMode::Triangles;  // its simplices are the constraints, as given
  try {
    ArgReader args(words);
    std::string v;
    while (!args.done()) {
      if (args.flag("--help") || args.flag("-h")) {
        out << cdt_help();
        return kOk;
      }
      if (args.value("-o", v) || args.value("--output", v)) output = v;
      else if (args.value("--format", v)) {
        format = format_named(v);
        if (!format) throw UsageError("unknown --format '" + v + "' (node, simplices; 3D: mesh, vtu, msh, msh22, tetgen, inp)");
      } else if (args.value("--delete", v)) {
        to_delete = parse_vertex_list(v);
      } else if (read_run_option(args, options)) {
      } else if (args.at_option()) throw UsageError("unknown option '" + args.peek() + "'");
      else if (input.empty()) input = args.take();
      else throw UsageError("cdt takes one FILE");
    }
    if (input.empty()) throw UsageError("no FILE given");
    if (output.empty()) throw UsageError("no -o OUTPUT given");
    if (options.snap > 0) throw UsageError("--snap repairs surface files (`mesh`); `cdt` takes a PLC file exactly as given");
    if (!format) format = format_of(output);
    if (!format) throw UsageError("cannot tell the format of '" + output + "' from its extension: use --format or .node .simplices (3D: .mesh .vtu .msh .inp)");
  } catch (const UsageError& e) {
    err << "sweepcdt: " << e.what() << "\n" << cdt_usage();
    return kUsage;
  }

  const auto start = std::chrono::steady_clock::now();
  Console console(err, options.quiet);
  install_interrupt_handler();
  FileResult r;
  r.input = input;
  r.outputs.push_back({output, format->word});
  {
    FileProgress progress(console, input, true);
    bool writing = false;
    try {
      progress.phase("reading");
      const io::AnyPlc plc = io::read_plc_file(input);
      r.seconds_read = since(start);
      std::visit([&](const auto& p) { triangulate(p, output, *format, options, to_delete, progress, r, writing); }, plc);
    } catch (const UsageError& e) {
      console.line(std::string("sweepcdt: ") + e.what());
      return kUsage;
    } catch (...) {
      const Failure f = describe_current_exception(input, writing);
      r.code = f.code;
      r.message = f.message;
      r.details = f.details;
    }
  }
  r.seconds_total = since(start);
  report_file(console, input + " -> " + output + ": " + std::to_string(r.dimension) + "D, " + summary_of(r), r, options.quiet);
  return write_stats_if_asked(console, RunSummary{"cdt", options, 1, r.seconds_total, r.code}, {r});
}

}  // namespace sweepcdt::cli
