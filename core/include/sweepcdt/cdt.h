// cdt(): the constrained Delaunay triangulation of a PLC — sweepcdt's library entry point.
//
//   Plc<3> plc = ...;                       // points, constraining triangles, exterior notations
//   Triangulation<3> tri = cdt(plc);        // throws PlcError, NoCdtError or CancelledError
//
// Every simplex of the result is constrained Delaunay for the points under the lifting-map
// perturbation of paper §6 (so degenerate, cospherical inputs get a well-defined answer), every
// constraining simplex is a facet, and the simplices cover exactly the triangulation domain: the
// convex hull without exterior notations, the facet-bounded domain with them.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sweepcdt/error.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt {

enum class Algorithm {
  GiftWrap,  // paper §2: O(n_v n_f n_s); the reference the sweeps are tested against
};

struct Progress {
  const char* phase;  // e.g. "gift-wrapping"
  uint64_t done;      // vertices reached so far
  uint64_t total;     // vertices in all (0 when unknown)
};

struct Options {
  Algorithm algorithm = Algorithm::GiftWrap;
  // Called now and then; return false to cancel (cdt() then throws CancelledError).
  std::function<bool(const Progress&)> progress;
};

// The PLC has no CDT (paper §2: a face that cannot be finished, or a simplex that is not
// constrained Delaunay). `witness` holds the vertex ids of the face or simplex concerned.
class NoCdtError : public Error {
 public:
  NoCdtError(const std::string& what, std::vector<uint32_t> witness) : Error(what), witness_(std::move(witness)) {}
  const std::vector<uint32_t>& witness() const { return witness_; }

 private:
  std::vector<uint32_t> witness_;
};

class CancelledError : public Error {
 public:
  CancelledError() : Error("cancelled") {}
};

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options = {});

}  // namespace sweepcdt
