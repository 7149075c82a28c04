#include "editable.h"

#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <string>
#include <variant>

#include "arrays.h"
#include "errors.h"
#include "options.h"
#include "plc_arrays.h"
#include "running.h"
#include "sweepcdt/editable_cdt.h"
#include "sweepcdt/perturbation_order.h"

namespace sweepcdt::python {
namespace py = pybind11;
namespace {

using AnyEditable = std::variant<EditableCdt<2>, EditableCdt<3>, EditableCdt<4>, EditableCdt<5>>;

template <class E>
constexpr int dimension_of = std::decay_t<decltype(std::declval<E>().snapshot().plc)>::dimension;

std::vector<int64_t> with_minus_one(const std::vector<uint32_t>& ids) {
  std::vector<int64_t> out(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) out[i] = ids[i] == kNone ? -1 : static_cast<int64_t>(ids[i]);
  return out;
}

// One EditableCdt of any dimension. Every method computes without the GIL, under the object's
// mutex, so that Python threads sharing one object take turns instead of racing (the GIL is
// released before the mutex is taken: a thread waiting for it holds nothing another needs).
class Editable {
  // First: member functions with deduced return types must be defined before they are used.
  template <class F>
  auto locked(F f) const {
    py::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    return std::visit(f, cdt_);
  }
  template <class F>
  auto locked(F f) {
    py::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    return std::visit(f, cdt_);
  }

 public:
  Editable(AnyEditable cdt, std::size_t num_ids) : cdt_(std::move(cdt)), num_ids_(num_ids) {}

  int dimension() const { return static_cast<int>(cdt_.index()) + 2; }
  std::size_t num_ids() const { return num_ids_; }
  std::size_t num_vertices() const { return locked([](const auto& e) { return e.num_vertices(); }); }
  std::size_t num_simplices() const { return locked([](const auto& e) { return e.num_simplices(); }); }
  bool has_vertex(int64_t v) const {
    return in_range(v) && locked([v](const auto& e) { return e.has_vertex(static_cast<uint32_t>(v)); });
  }

  void remove_vertex(int64_t v) {
    require_in_range(v);
    locked([v](auto& e) { e.remove_vertex(static_cast<uint32_t>(v)); });
  }

  // Deletes the vertices in order; a refusal (NoCdtError, VertexRemovalError: the mesh unchanged)
  // is recorded and the next one tried. Returns (removed ids, [(id, exception)]).
  py::tuple remove_vertices(const std::vector<int64_t>& ids, py::object progress) {
    std::vector<int64_t> removed;
    std::vector<std::pair<int64_t, std::exception_ptr>> refused;
    Watch watch(std::move(progress));
    try {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      std::visit(
          [&](auto& e) {
            for (std::size_t k = 0; k < ids.size(); ++k) {
              // Ctrl-C and the callback are looked at every 64 deletions (64 take ~10 ms in 3D, ~0.2 s in 4D).
              if (k % 64 == 0 && !watch.report("deleting vertices", k, ids.size())) throw CancelledError();
              try {
                require_in_range(ids[k]);
                e.remove_vertex(static_cast<uint32_t>(ids[k]));
                removed.push_back(ids[k]);
              } catch (const NoCdtError&) {
                refused.emplace_back(ids[k], std::current_exception());
              } catch (const VertexRemovalError&) {
                refused.emplace_back(ids[k], std::current_exception());
              }
            }
          },
          cdt_);
    } catch (const CancelledError&) {
      watch.rethrow();
    }
    py::list why;
    for (const auto& [v, error] : refused) why.append(py::make_tuple(v, removal_exception(error, v)));
    return py::make_tuple(py::cast(removed), why);
  }

  py::dict snapshot() const {
    return std::visit(
        [&](const auto& e) {
          constexpr int D = dimension_of<decltype(e)>;
          typename std::decay_t<decltype(e)>::Snapshot s;
          {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            s = e.snapshot();
          }
          py::dict r = plc_dict<D>(s.plc);
          Triangulation<D>& tri = s.triangulation;
          swap_orientation_convention<D>(tri.simplices);
          r["simplices"] = to_numpy<int64_t>(tri.simplices, D + 1);
          r["regions"] = to_numpy<int32_t>(tri.regions, 0);
          r["num_input_points"] = tri.num_input_points;
          r["steiner_simplices"] = to_numpy<int64_t>(with_minus_one(tri.steiner_on), 0);
          r["old_ids"] = to_numpy<int64_t>(s.old_ids, 0);
          r["num_ids"] = num_ids_;
          r["perturbation_rank"] =
              tri.perturbation_rank.empty() ? py::object(py::none()) : py::object(to_numpy<int64_t>(tri.perturbation_rank, 0));
          return r;
        },
        cdt_);
  }

  py::dict plc_without(int64_t v) const {
    require_in_range(v);
    return std::visit(
        [&](const auto& e) {
          constexpr int D = dimension_of<decltype(e)>;
          Plc<D> plc;
          std::vector<uint32_t> old_ids;
          {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            plc = e.plc_without(static_cast<uint32_t>(v));
            // plc_without numbers the vertices left as snapshot() would after the deletion: in id order.
            for (uint32_t x = 0; x < num_ids_; ++x)
              if (x != v && e.has_vertex(x)) old_ids.push_back(x);
          }
          py::dict r = plc_dict<D>(plc);
          r["old_ids"] = to_numpy<int64_t>(old_ids, 0);
          return r;
        },
        cdt_);
  }

 private:
  bool in_range(int64_t v) const { return v >= 0 && static_cast<uint64_t>(v) < num_ids_; }
  void require_in_range(int64_t v) const {
    // As core says it for ids it knows; an id that does not fit uint32 must not be wrapped into one.
    if (!in_range(v)) throw VertexRemovalError("vertex " + std::to_string(v) + " is not a vertex of the triangulation");
  }

  template <int D>
  static py::dict plc_dict(const Plc<D>& plc) {
    py::dict r;
    r["dimension"] = D;
    r["points"] = to_numpy<double>(plc.points, D);
    r["constraints"] = to_numpy<int64_t>(plc.simplices, D);
    std::vector<int64_t> exterior;
    for (ExteriorSide side : plc.exterior) exterior.push_back(exterior_code(side));
    r["exterior"] = plc.exterior.empty() ? py::object(py::none()) : py::object(to_numpy<int64_t>(exterior, 0));
    r["tags"] = plc.tags.empty() ? py::object(py::none()) : py::object(to_numpy<int64_t>(plc.tags, 0));
    return r;
  }

  mutable std::mutex mutex_;
  AnyEditable cdt_;
  std::size_t num_ids_;  // ids are 0 .. num_ids_ - 1 and never change while editing
};

// From a PLC: its CDT, as sweepcdt.cdt computes it, with the PLC actually triangulated (Steiner
// points and re-triangulated coplanar facets included: EditableCdt needs the constraints that are
// faces of the triangulation).
template <int D>
std::unique_ptr<Editable> from_plc(PlcArrays arrays, const RunKeywords& k, Watch& watch) {
  const Plc<D> plc = plc_of<D>(std::move(arrays));
  Options options;
  options.algorithm = k.algorithm;
  options.steiner = k.steiner;
  options.facets = k.facets;
  options.progress = watch.core_callback();
  py::gil_scoped_release release;
  Plc<D> triangulated;
  Triangulation<D> tri = cdt(plc, options, &triangulated);
  const std::size_t n = tri.num_points();
  return std::make_unique<Editable>(AnyEditable(std::in_place_type<EditableCdt<D>>, std::move(triangulated), std::move(tri)), n);
}

std::unique_ptr<Editable> editable_from_plc(const py::handle& points, const py::handle& constraints, const py::handle& exterior,
                                            const py::handle& tags, const std::optional<std::string>& algorithm,
                                            const std::optional<std::string>& steiner, const std::optional<std::string>& facets,
                                            py::object progress) {
  PlcArrays arrays = plc_arrays(points, constraints, exterior, tags, "constraints");
  const int d = arrays.dimension;
  const RunKeywords k = run_keywords(algorithm, steiner ? steiner : std::optional<std::string>("none"), facets, std::nullopt, false);
  if (k.steiner == SteinerMode::Auto && d != 3) throw py::value_error("steiner='auto' is implemented for D = 3 only");
  Watch watch(std::move(progress));
  try {
    switch (d) {
      case 2: return from_plc<2>(std::move(arrays), k, watch);
      case 3: return from_plc<3>(std::move(arrays), k, watch);
      case 4: return from_plc<4>(std::move(arrays), k, watch);
      default: return from_plc<5>(std::move(arrays), k, watch);
    }
  } catch (const CancelledError&) {
    watch.rethrow();
  }
}

// From a triangulation the caller has (a TetMesh, a file): it must be a CDT of the constraints,
// which EditableCdt takes on trust — so it is validated here, under the first of cdt()'s
// perturbation orders that makes it one, as `sweepcdt check` does (a mesh made under a later order
// is a CDT under that order only, and deletions must keep to it).
template <int D>
std::unique_ptr<Editable> from_triangulation(PlcArrays arrays, const std::vector<int64_t>& simplices, const std::vector<int64_t>& regions) {
  const Plc<D> plc = plc_of<D>(std::move(arrays));
  const std::size_t n = plc.num_points();
  Triangulation<D> tri = triangulation_of<D>(plc, {});
  for (std::size_t i = 0; i < simplices.size(); ++i) {
    if (simplices[i] < 0 || static_cast<uint64_t>(simplices[i]) >= n)
      throw py::value_error("simplices[" + std::to_string(i / (D + 1)) + "]: point id " + std::to_string(simplices[i]) +
                            " is not in [0, " + std::to_string(n) + ")");
    tri.simplices.push_back(static_cast<uint32_t>(simplices[i]));
  }
  swap_orientation_convention<D>(tri.simplices);
  for (int64_t r : regions) {
    if (r < INT32_MIN || r > INT32_MAX) throw py::value_error("regions: " + std::to_string(r) + " does not fit int32");
    tri.regions.push_back(static_cast<int32_t>(r));
  }
  py::gil_scoped_release release;
  check(plc);
  compute_neighbors(tri);
  ValidationReport first;
  for (int order = 0; order < kPerturbationOrders; ++order) {
    if (order > 0) tri.perturbation_rank = perturbation_rank(plc, order);
    ValidationReport report = validate(tri, plc);
    if (report.ok())
      return std::make_unique<Editable>(AnyEditable(std::in_place_type<EditableCdt<D>>, plc, std::move(tri)), n);
    if (order == 0) first = std::move(report);
    // Only the Delaunay test depends on the order: anything else fails under every order.
    if (first.counts.size() != 1 || first.count("locally-delaunay") == 0) break;
  }
  throw NotValid("the simplices are not the CDT of the constraints: " + first.summary(), std::move(first));
}

std::unique_ptr<Editable> editable_from_triangulation(const py::handle& points, const py::handle& simplices,
                                                      const py::handle& constraints, const py::handle& exterior,
                                                      const py::handle& tags, const py::handle& regions) {
  PlcArrays arrays = plc_arrays(points, constraints, exterior, tags, "constraints");
  const int d = arrays.dimension;
  const std::vector<int64_t> s = index_matrix(simplices, "simplices", d + 1);
  const std::vector<int64_t> r = regions.is_none() ? std::vector<int64_t>{} : index_vector(regions, "regions", s.size() / (d + 1));
  switch (d) {
    case 2: return from_triangulation<2>(std::move(arrays), s, r);
    case 3: return from_triangulation<3>(std::move(arrays), s, r);
    case 4: return from_triangulation<4>(std::move(arrays), s, r);
    default: return from_triangulation<5>(std::move(arrays), s, r);
  }
}

}  // namespace

void register_editable(py::module_& m) {
  py::class_<Editable>(m, "EditableCdt")
      .def_property_readonly("dimension", &Editable::dimension)
      .def_property_readonly("num_ids", &Editable::num_ids)
      .def_property_readonly("num_vertices", &Editable::num_vertices)
      .def_property_readonly("num_simplices", &Editable::num_simplices)
      .def("has_vertex", &Editable::has_vertex, py::arg("v"))
      .def("remove_vertex", &Editable::remove_vertex, py::arg("v"))
      .def("remove_vertices", &Editable::remove_vertices, py::arg("vertices"), py::arg("progress"))
      .def("snapshot", &Editable::snapshot)
      .def("plc_without", &Editable::plc_without, py::arg("v"));
  m.def("editable_from_plc", &editable_from_plc, py::arg("points"), py::arg("constraints"), py::arg("exterior"), py::arg("tags"),
        py::arg("algorithm"), py::arg("steiner"), py::arg("facets"), py::arg("progress"));
  m.def("editable_from_triangulation", &editable_from_triangulation, py::arg("points"), py::arg("simplices"),
        py::arg("constraints"), py::arg("exterior"), py::arg("tags"), py::arg("regions"));
}

}  // namespace sweepcdt::python
