// Vertex: how predicates see a point — its coordinates and its index in the input.
//
// The index matters only to the symbolic perturbation (paper §6), which is ordered by vertex index,
// never by memory address: the same vertices with the same indices always give the same answers.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace sweepcdt::predicates {

struct Vertex {
  const double* x;  // D coordinates
  uint32_t id;      // index used to order the perturbation (lower index = larger perturbation)
};

// A simplex given by its vertices, in order (the order defines its orientation).
template <int N>
using Vertices = std::array<Vertex, N>;

// Plain coordinates, for predicates that no perturbation affects.
template <int N>
using Coords = std::array<const double*, N>;

template <std::size_t N>
std::array<const double*, N> coords_of(const std::array<Vertex, N>& v) {
  std::array<const double*, N> c;
  for (std::size_t i = 0; i < N; ++i) c[i] = v[i].x;
  return c;
}

}  // namespace sweepcdt::predicates
