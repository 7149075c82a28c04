// Argument handling and the batch loop of `sweepcdt mesh`; one file's work is convert_surface().
//
// Several outputs of one input (-o a.mesh -o a.vtu, or --format mesh,vtu in batch) share one CDT.
// Batch: one output per input and format in --out-dir, named after the input's stem. --threads N converts N
// files at a time (std::thread, each file on one thread): cdt() is deterministic, so the files are
// byte-identical to a one-thread run; only the order of the messages may differ.
#include "mesh_command.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <ostream>
#include <thread>

#include "args.h"
#include "convert_surface.h"
#include "errors.h"
#include "exit_codes.h"
#include "progress.h"
#include "report.h"
#include "stats.h"
#include "usage.h"

namespace sweepcdt::cli {
namespace {

namespace fs = std::filesystem;

struct MeshRequest {
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;  // -o, once per output (one input)
  std::string out_dir;               // --out-dir
  std::vector<io::MeshFormat> formats;  // --format F[,F...]
  unsigned threads = 1;
  RunOptions options;
};

const char* extension_of(io::MeshFormat f) {
  switch (f) {
    case io::MeshFormat::Medit: return ".mesh";
    case io::MeshFormat::Vtu: return ".vtu";
    case io::MeshFormat::Gmsh41:
    case io::MeshFormat::Gmsh22: return ".msh";
    case io::MeshFormat::TetGen: return ".node";
    case io::MeshFormat::Abaqus: return ".inp";
  }
  return "";
}

// --format msh22 writes a .msh; any TetGen name is fine: these pairs are not conflicts.
bool compatible(io::MeshFormat named, io::MeshFormat by_extension) {
  if (named == by_extension) return true;
  const auto gmsh = [](io::MeshFormat f) { return f == io::MeshFormat::Gmsh41 || f == io::MeshFormat::Gmsh22; };
  return gmsh(named) && gmsh(by_extension);
}

std::vector<io::MeshFormat> formats_named(const std::string& list) {
  std::vector<io::MeshFormat> formats;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = list.find(',', start);
    const std::string word = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto f = io::mesh_format_named(word);
    if (!f) throw UsageError("unknown --format '" + word + "' (mesh, vtu, msh, msh22, tetgen, inp)");
    if (std::find(formats.begin(), formats.end(), *f) == formats.end()) formats.push_back(*f);
    if (comma == std::string::npos) return formats;
    start = comma + 1;
  }
}

MeshRequest parse(const std::vector<std::string>& words) {
  MeshRequest req;
  ArgReader args(words);
  std::string v;
  while (!args.done()) {
    if (args.value("-o", v) || args.value("--output", v)) {
      req.outputs.push_back(v);
    } else if (args.value("--out-dir", v)) {
      req.out_dir = v;
    } else if (args.value("--format", v)) {
      req.formats = formats_named(v);
    } else if (args.value("--threads", v)) {
      req.threads = parse_count("--threads", v, 256);
    } else if (read_run_option(args, req.options)) {
    } else if (args.at_option()) {
      throw UsageError("unknown option '" + args.peek() + "'");
    } else {
      req.inputs.push_back(args.take());
    }
  }
  if (req.inputs.empty()) throw UsageError("no INPUT given");
  if (req.outputs.empty() == req.out_dir.empty()) throw UsageError("give either -o OUTPUT (one input) or --out-dir DIR");
  if (req.out_dir.empty() && req.inputs.size() > 1) throw UsageError("-o takes one INPUT; for several use --out-dir DIR");
  if (req.formats.empty() && !req.out_dir.empty()) req.formats = {io::MeshFormat::Medit};  // batch default, documented
  if (!req.out_dir.empty()) {
    for (std::size_t a = 0; a < req.formats.size(); ++a)
      for (std::size_t b = 0; b < a; ++b)
        if (std::string(extension_of(req.formats[a])) == extension_of(req.formats[b]))
          throw UsageError(std::string("--format ") + io::to_string(req.formats[b]) + " and " + io::to_string(req.formats[a]) + " both write " +
                           extension_of(req.formats[a]) + " files");
  }
  if (!req.outputs.empty() && req.formats.size() > 1) throw UsageError("with -o, --format names one format (the outputs' extensions name the others)");
  return req;
}

// Each input's outputs. Batch: DIR/<stem>.<ext> per format; two inputs with one stem would
// overwrite each other, which is a usage error.
std::vector<std::vector<MeshTarget>> targets_of(const MeshRequest& req) {
  if (!req.outputs.empty()) {
    std::vector<MeshTarget> targets;
    std::set<std::string> seen;
    for (const auto& output : req.outputs) {
      const auto by_extension = io::mesh_format_of(output);
      if (req.formats.empty() && !by_extension)
        throw UsageError("cannot tell the format of '" + output + "' from its extension: use --format or .mesh .vtu .msh .node .inp");
      if (!req.formats.empty() && by_extension && !compatible(req.formats[0], *by_extension))
        throw UsageError("'" + output + "' looks like " + io::to_string(*by_extension) + " but --format says " + io::to_string(req.formats[0]));
      if (!seen.insert(output).second) throw UsageError("-o '" + output + "' given twice");
      targets.push_back({output, req.formats.empty() ? *by_extension : req.formats[0]});
    }
    return {targets};
  }
  std::vector<std::vector<MeshTarget>> all;
  std::map<std::string, std::string> taken;
  for (const auto& input : req.inputs) {
    std::vector<MeshTarget> targets;
    for (const io::MeshFormat format : req.formats) {
      const std::string name = (fs::path(req.out_dir) / fs::path(input).stem()).string() + extension_of(format);
      const auto [it, fresh] = taken.emplace(name, input);
      if (!fresh) throw UsageError("'" + it->second + "' and '" + input + "' would both be written to '" + name + "'");
      targets.push_back({name, format});
    }
    all.push_back(std::move(targets));
  }
  return all;
}

std::string names_of(const std::vector<OutputFile>& outputs) {
  std::string s;
  for (const auto& o : outputs) s += (s.empty() ? "" : ", ") + o.file;
  return s;
}

}  // namespace

int run_mesh(const std::vector<std::string>& words, std::ostream& out, std::ostream& err) {
  for (const auto& w : words)
    if (w == "--help" || w == "-h") {
      out << mesh_help();
      return kOk;
    }
  MeshRequest req;
  std::vector<std::vector<MeshTarget>> targets;
  try {
    req = parse(words);
    targets = targets_of(req);
  } catch (const UsageError& e) {
    err << "sweepcdt: " << e.what() << "\n" << mesh_usage();
    return kUsage;
  }
  const auto start = std::chrono::steady_clock::now();
  Console console(err, req.options.quiet);
  if (!req.out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(req.out_dir, ec);
    if (ec) {
      console.line("sweepcdt: " + req.out_dir + ": cannot create the output folder: " + ec.message());
      return kWriteFailed;
    }
  }
  install_interrupt_handler();

  const std::size_t n = req.inputs.size();
  std::vector<FileResult> results(n);
  std::vector<char> started(n, 0);
  std::atomic<std::size_t> next{0};
  const unsigned threads = static_cast<unsigned>(std::min<std::size_t>(req.threads, n));
  // Files converted at once share the cores: each computation gets its part of them.
  if (threads > 1) req.options.core_threads = std::max(1u, std::thread::hardware_concurrency() / threads);
  const auto work = [&] {
    for (std::size_t i; (i = next++) < n && !interrupted();) {
      started[i] = 1;
      std::string label = req.inputs[i];
      if (n > 1) label.insert(0, std::string(1, '[').append(std::to_string(i + 1)).append("/").append(std::to_string(n)).append("] "));
      FileProgress progress(console, label, threads == 1);
      results[i] = convert_surface(req.inputs[i], targets[i], req.options, progress);
      const FileResult& r = results[i];
      report_file(console, label + " -> " + names_of(r.outputs) + ": " + summary_of(r), r, req.options.quiet);
    }
  };
  if (threads <= 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    for (auto& t : pool) t.join();
  }

  int code = kOk;
  std::size_t not_started = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!started[i]) {
      results[i].input = req.inputs[i];
      for (const auto& t : targets[i]) results[i].outputs.push_back({t.file, io::to_string(t.format)});
      results[i].code = kCancelled;
      results[i].message = "not started (cancelled)";
      ++not_started;
    }
    code = worst(code, results[i].code);
  }
  if (not_started) console.line("sweepcdt: cancelled (Ctrl-C): " + std::to_string(not_started) + " files not started");
  if (n > 1 && !req.options.quiet) {
    std::size_t ok = 0;
    for (const auto& r : results) ok += r.code == kOk;
    console.line(std::to_string(ok) + " of " + std::to_string(n) + " files converted");
  }
  const RunSummary run{"mesh", req.options, threads, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), code};
  return write_stats_if_asked(console, run, results);
}

}  // namespace sweepcdt::cli
