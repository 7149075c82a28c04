#include "stats.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include "sweepcdt/io/error.h"

namespace sweepcdt::cli {
namespace {

const char* status_word(int code) {
  switch (code) {
    case kOk: return "ok";
    case kBadInput: return "bad-input";
    case kNoCdt: return "no-cdt";
    case kWriteFailed: return "write-failed";
    case kNotValid: return "not-valid";
    case kCancelled: return "cancelled";
    case kUsage: return "usage";
  }
  return "internal-error";
}

nlohmann::ordered_json file_json(const FileResult& r, double run_snap) {
  nlohmann::ordered_json j;
  j["input"] = r.input;
  j["outputs"] = nlohmann::ordered_json::array();
  for (const OutputFile& o : r.outputs) j["outputs"].push_back({{"file", o.file}, {"format", o.format}});
  j["status"] = status_word(r.code);
  j["exit_code"] = r.code;
  if (!r.message.empty()) j["message"] = r.message;
  if (!r.warnings.empty()) j["warnings"] = r.warnings;
  j["dimension"] = r.dimension;
  j["input_vertices"] = r.input_points;
  j[r.dimension == 3 ? "input_triangles" : "input_simplices"] = r.input_simplices;
  if (run_snap > 0)  // --snap: the surface was moved before meshing (sweepcdt/io/snap.h)
    j["snap"] = {{"tolerance", r.snap.tolerance},
                 {"coordinates_moved", r.snap.coordinates_moved},
                 {"points_moved", r.snap.points_moved},
                 {"points_merged", r.snap.points_merged},
                 {"edges_flattened", r.snap.edges_flattened},
                 {"largest_move", r.snap.largest_move}};
  if (r.computed) {
    j["algorithm"] = to_string(r.cdt.algorithm);  // the one that ran (sweep-plane falls back to the sphere on hulls)
    j["steiner_points"] = r.cdt.steiner_points;
    j["steiner_points_removed"] = r.cdt.steiner_points_removed;
    j["steiner_deletions_tried"] = r.cdt.steiner_deletions_tried;
    j["steiner_retries_skipped"] = r.cdt.steiner_retries_skipped;
    j["steiner_refused_early"] = r.cdt.steiner_refused_early;
    j["steiner_rounds"] = r.cdt.steiner_rounds;
    j["steiner_attempts"] = r.cdt.steiner_attempts;
    j["facets"] = r.cdt.facets;
    j["facet_flips"] = r.cdt.facet_flips;
    j[r.dimension == 3 ? "tetrahedra" : "simplices"] = r.simplices;
    if (r.dimension == 3) {
      j["boundary_triangles"] = r.boundary_triangles;
      j["regions"] = r.regions;
    }
    j["queue_pushes"] = r.cdt.queue_pushes;
    j["queue_pops"] = r.cdt.queue_pops;
    j["stale_pops"] = r.cdt.stale_pops;
    j["drop_moves"] = r.cdt.drop_moves;
    j["missing_constraints"] = r.cdt.missing_constraints;  // cavity sweep: constraints no Delaunay face
    j["cavity_tetrahedra"] = r.cdt.cavity_tetrahedra;      // cavity sweep: Delaunay tetrahedra swept again
    j["perturbation_order"] = r.cdt.perturbation_order;  // paper §6: 0 = vertex ids (sweepcdt/perturbation_order.h)
    j["validated"] = r.validated;
    j["check_recorded"] = r.cdt.check_recorded;  // cdt() reused the importer's intersection check
    j["tetrahedralization_recorded"] = r.cdt.tetrahedralization_recorded;  // and the importer's tetrahedralization
  }
  // Runs made, one per perturbation order tried (paper §6); also when none gave a CDT.
  if (r.computed || r.code == kNoCdt) j["perturbation_orders"] = r.cdt.perturbation_orders;
  nlohmann::ordered_json s;
  s["read"] = r.seconds_read;
  if (r.computed) {
    s["check"] = r.cdt.seconds_check;  // the PLC check inside cdt() (O(n + m) when check_recorded)
    s["setup"] = r.cdt.seconds_setup;  // Steiner points and the seed
    s["build"] = r.cdt.seconds_build;  // the sweep (or gift-wrapping)
    s["finish"] = r.cdt.seconds_finish;  // neighbours, regions, cdt()'s own validate()
  }
  s["validate"] = r.seconds_validate;
  s["write"] = r.seconds_write;
  s["total"] = r.seconds_total;
  j["seconds"] = s;
  return j;
}

}  // namespace

uint64_t peak_memory_bytes() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<uint64_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

void write_stats(const std::string& file, const RunSummary& run, const std::vector<FileResult>& results) {
  nlohmann::ordered_json j;
  j["sweepcdt_version"] = SWEEPCDT_VERSION;
  j["command"] = run.command;
  j["algorithm"] = to_string(run.options.algorithm);  // requested; per file: the one that ran
  j["steiner"] = to_string(run.options.steiner);
  j["facets"] = to_string(run.options.facets);
  j["snap"] = run.options.snap;  // relative tolerance; 0: the input as given
  j["check"] = run.options.check;
  j["threads"] = run.threads;
  j["exit_code"] = run.exit_code;
  j["seconds"] = run.seconds;
  j["peak_memory_bytes"] = peak_memory_bytes();  // the whole process: with threads, of all files at once
  j["files"] = nlohmann::ordered_json::array();
  for (const FileResult& r : results) j["files"].push_back(file_json(r, run.options.snap));

  const std::filesystem::path path(file);
  const std::filesystem::path tmp = path.string() + ".tmp" + std::to_string(::getpid());
  const auto fail = [&](const std::string& why) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    return io::InputError(io::InputErrorKind::Unreadable, file, io::Location::none(), "cannot write the statistics: " + why);
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw fail("cannot create a file there");
    out << j.dump(2) << "\n";
    out.flush();
    if (!out) throw fail("write failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw fail(ec.message());
}

}  // namespace sweepcdt::cli
