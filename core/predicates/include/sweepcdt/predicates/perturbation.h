// The lifting-map symbolic perturbation of paper §6.
//
// Every vertex v is lifted to (v, |v|^2) in E^{D+1} and then, symbolically, moved down by eps_v,
// where eps_a >> eps_b whenever id(a) < id(b) (lower index = larger perturbation). Coplanar vertices
// stay coplanar: only tests that involve spheres change.
//
// insphere is linear in the lifted column, so with lifted heights w_i - eps_i
//   det M(eps) = det M(0) - sum_i eps_i * C_i,
// where C_i = (-1)^{i+D} orient(p_0..p_{D+1} without p_i) is the cofactor of w_i. When det M(0) = 0
// the sign is that of -C_i for the vertex of least id with C_i != 0:
//   insphere_perturbed = (-1)^{i+D+1} * orient(all but p_i).
// Identities (tested):
//   * never Zero unless all D+2 points lie in one hyperplane;
//   * swapping two arguments flips the sign (it is a determinant);
//   * if p_{D+1} has the least id, the answer is "inside" (= orient(p_0..p_D)): the perturbed query
//     point is moved below the hyperplane through the other lifted points.
#pragma once
#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

template <int D>
Sign insphere_perturbed(const Vertices<D + 2>& p);

// True when q is strictly inside the (perturbed) circumsphere of the D-simplex s. s must be
// non-degenerate; its orientation does not matter.
template <int D>
bool inside_circumsphere(const Vertices<D + 1>& s, const Vertex& q);

}  // namespace sweepcdt::predicates
