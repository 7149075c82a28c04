// An independent exact reference for the predicates, for tests only.
//
// Everything here is plain rational linear algebra with GMP's mpq_class: determinants and linear
// solves by Gaussian elimination, null vectors, Gram-Schmidt without normalisation. It deliberately
// shares no code (and no formula shape) with the library's filters, dyadic arithmetic or Laplace
// determinants, so that agreement between the two is evidence rather than tautology.
//
// Symbolic perturbations are replaced by concrete tiny rationals:
//   * lifting perturbation: eps for the vertex of rank r (rank by id, lowest id = rank 0) is
//     2^{-100 (r + 1)}; the lifted height of a vertex is |p|^2 - eps;
//   * ray directions: delta = 2^-100.
// Every quantity involved is polynomial of low degree in these, with coefficients far below 2^100 on
// the small integer inputs where the tests use them, so the concrete value has the sign of the
// symbolic one.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sweepcdt::ref {

using Q = mpq_class;
using Vec = std::vector<Q>;
using Mat = std::vector<Vec>;  // row-major: Mat[row][column]

// ---- scalars and vectors ------------------------------------------------------------------------

inline int sign(const Q& q) { return sgn(q); }

// mpq_set_d converts every finite double exactly.
inline Q exact(double d) { return Q(d); }

inline Vec point(const double* x, int dim) {
  Vec v(dim);
  for (int k = 0; k < dim; ++k) v[k] = exact(x[k]);
  return v;
}

inline Q pow2(long e) {
  Q r(1);
  if (e >= 0)
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  return r;
}

inline Vec sub(const Vec& a, const Vec& b) {
  Vec r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] - b[i];
  return r;
}

inline Vec add(const Vec& a, const Vec& b) {
  Vec r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] + b[i];
  return r;
}

inline Vec scale(const Q& s, const Vec& a) {
  Vec r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = s * a[i];
  return r;
}

inline Q dot(const Vec& a, const Vec& b) {
  Q r(0);
  for (std::size_t i = 0; i < a.size(); ++i) r += a[i] * b[i];
  return r;
}

inline bool is_zero(const Vec& a) {
  return std::all_of(a.begin(), a.end(), [](const Q& q) { return sgn(q) == 0; });
}

// Lexicographic comparison: -1, 0 or +1.
inline int lex_compare(const Vec& a, const Vec& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int c = cmp(a[i], b[i]);
    if (c != 0) return c < 0 ? -1 : 1;
  }
  return 0;
}

// ---- Gaussian elimination -----------------------------------------------------------------------

// Determinant of a square matrix by elimination with row swaps.
inline Q det(Mat a) {
  const std::size_t n = a.size();
  Q d(1);
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t piv = col;
    while (piv < n && sgn(a[piv][col]) == 0) ++piv;
    if (piv == n) return Q(0);
    if (piv != col) {
      std::swap(a[piv], a[col]);
      d = -d;
    }
    d *= a[col][col];
    for (std::size_t r = col + 1; r < n; ++r) {
      if (sgn(a[r][col]) == 0) continue;
      const Q f = a[r][col] / a[col][col];
      for (std::size_t k = col; k < n; ++k) a[r][k] -= f * a[col][k];
    }
  }
  return d;
}

// Reduced row echelon form in place; returns the pivot column of each pivot row.
inline std::vector<std::size_t> rref(Mat& a) {
  std::vector<std::size_t> pivots;
  if (a.empty()) return pivots;
  const std::size_t rows = a.size(), cols = a[0].size();
  std::size_t r = 0;
  for (std::size_t col = 0; col < cols && r < rows; ++col) {
    std::size_t piv = r;
    while (piv < rows && sgn(a[piv][col]) == 0) ++piv;
    if (piv == rows) continue;
    std::swap(a[piv], a[r]);
    const Q inv = 1 / a[r][col];
    for (std::size_t k = col; k < cols; ++k) a[r][k] *= inv;
    for (std::size_t i = 0; i < rows; ++i) {
      if (i == r || sgn(a[i][col]) == 0) continue;
      const Q f = a[i][col];
      for (std::size_t k = col; k < cols; ++k) a[i][k] -= f * a[r][k];
    }
    pivots.push_back(col);
    ++r;
  }
  return pivots;
}

inline int rank(Mat a) { return static_cast<int>(rref(a).size()); }

// Solves the square system a x = b; nullopt when a is singular.
inline std::optional<Vec> solve(const Mat& a, const Vec& b) {
  const std::size_t n = a.size();
  Mat aug(n, Vec(n + 1));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n; ++k) aug[i][k] = a[i][k];
    aug[i][n] = b[i];
  }
  const auto pivots = rref(aug);
  if (pivots.size() < n || pivots.back() >= n) return std::nullopt;
  Vec x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = aug[i][n];
  return x;
}

// A non-zero vector spanning the null space of a, when that null space is one-dimensional.
inline std::optional<Vec> null_vector(Mat a) {
  if (a.empty()) return std::nullopt;
  const std::size_t cols = a[0].size();
  const auto pivots = rref(a);
  if (pivots.size() + 1 != cols) return std::nullopt;
  std::size_t free_col = 0;
  while (std::find(pivots.begin(), pivots.end(), free_col) != pivots.end()) ++free_col;
  Vec x(cols, Q(0));
  x[free_col] = 1;
  for (std::size_t r = 0; r < pivots.size(); ++r) x[pivots[r]] = -a[r][free_col];
  return x;
}

// ---- orientation and insphere -------------------------------------------------------------------

// sign det [p_i - p_D]_{i<D} for D+1 points in R^D.
inline int orient(const std::vector<Vec>& p) {
  const std::size_t d = p.size() - 1;
  Mat m(d, Vec(d));
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t k = 0; k < d; ++k) m[i][k] = p[i][k] - p[d][k];
  return sign(det(m));
}

// sign det [[p_i, 1]]_{i<=D}: the same sign, stated differently.
inline int orient_homogeneous(const std::vector<Vec>& p) {
  const std::size_t d = p.size() - 1;
  Mat m(d + 1, Vec(d + 1));
  for (std::size_t i = 0; i <= d; ++i) {
    for (std::size_t k = 0; k < d; ++k) m[i][k] = p[i][k];
    m[i][d] = 1;
  }
  return sign(det(m));
}

// sign det [p_i - p_{D+1}, |p_i - p_{D+1}|^2]_{i<=D} for D+2 points in R^D.
inline int insphere(const std::vector<Vec>& p) {
  const std::size_t d = p.size() - 2;
  Mat m(d + 1, Vec(d + 1));
  for (std::size_t i = 0; i <= d; ++i) {
    const Vec a = sub(p[i], p[d + 1]);
    for (std::size_t k = 0; k < d; ++k) m[i][k] = a[k];
    m[i][d] = dot(a, a);
  }
  return sign(det(m));
}

// The concrete lifting perturbation: eps of the vertex whose id has rank r among `ids`.
inline Q eps_for_rank(int r) { return pow2(-100L * (r + 1)); }

class EpsTable {
 public:
  explicit EpsTable(std::vector<uint32_t> ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (std::size_t r = 0; r < ids.size(); ++r) eps_.emplace(ids[r], eps_for_rank(static_cast<int>(r)));
  }
  const Q& operator()(uint32_t id) const {
    const auto it = eps_.find(id);
    if (it == eps_.end()) throw std::out_of_range("EpsTable: unknown id");
    return it->second;
  }

 private:
  std::map<uint32_t, Q> eps_;
};

// sign det [[p_i, |p_i|^2 - eps_i, 1]]_{i<=D+1}: insphere of the perturbed lifted points.
inline int lifted_insphere(const std::vector<Vec>& p, const Vec& eps) {
  const std::size_t d = p.size() - 2;
  Mat m(d + 2, Vec(d + 2));
  for (std::size_t i = 0; i < d + 2; ++i) {
    for (std::size_t k = 0; k < d; ++k) m[i][k] = p[i][k];
    m[i][d] = dot(p[i], p[i]) - eps[i];
    m[i][d + 1] = 1;
  }
  return sign(det(m));
}

// The hyperplane  w = 2 O.x + c  through the lifted points (p_i, |p_i|^2 - eps_i): O is the
// (perturbed) circumcentre, c + |O|^2 the squared radius.
struct LiftedSphere {
  Vec center;
  Q c;
};

inline std::optional<LiftedSphere> lifted_sphere(const std::vector<Vec>& p, const Vec& eps) {
  const std::size_t d = p.size() - 1;
  Mat a(d + 1, Vec(d + 1));
  Vec b(d + 1);
  for (std::size_t i = 0; i <= d; ++i) {
    for (std::size_t k = 0; k < d; ++k) a[i][k] = 2 * p[i][k];
    a[i][d] = 1;
    b[i] = dot(p[i], p[i]) - eps[i];
  }
  const auto x = solve(a, b);
  if (!x) return std::nullopt;
  LiftedSphere s;
  s.center.assign(x->begin(), x->begin() + static_cast<std::ptrdiff_t>(d));
  s.c = (*x)[d];
  return s;
}

// Power of q: |q - O|^2 - r^2 = |q|^2 - (2 O.q + c).
inline Q power(const LiftedSphere& s, const Vec& q) { return dot(q, q) - 2 * dot(s.center, q) - s.c; }

// ---- hyperplanes and sides ----------------------------------------------------------------------

struct Hyperplane {
  Vec n;  // n.x = c
  Q c;
};

// The hyperplane through D points of R^D; nullopt when they do not span one.
inline std::optional<Hyperplane> hyperplane_through(const std::vector<Vec>& f) {
  const std::size_t d = f[0].size();
  Mat a(f.size(), Vec(d + 1));
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (std::size_t k = 0; k < d; ++k) a[i][k] = f[i][k];
    a[i][d] = -1;
  }
  const auto x = null_vector(a);
  if (!x) return std::nullopt;
  Hyperplane h{Vec(x->begin(), x->begin() + static_cast<std::ptrdiff_t>(d)), (*x)[d]};
  if (is_zero(h.n)) return std::nullopt;
  return h;
}

inline Q eval(const Hyperplane& h, const Vec& x) { return dot(h.n, x) - h.c; }

// The sign of eval() on the "behind" side (paper §3). Plane: the side of -infinity along the first
// axis the hyperplane is not parallel to. Sphere: the side of the first seed vertex off the
// hyperplane (0 when every seed vertex is on it).
inline int behind_eval_sign_plane(const Hyperplane& h) {
  for (const Q& nk : h.n)
    if (sgn(nk) != 0) return -sgn(nk);
  return 0;
}

inline int behind_eval_sign_sphere(const Hyperplane& h, const std::vector<Vec>& delta) {
  for (const Vec& dj : delta)
    if (const int s = sign(eval(h, dj)); s != 0) return s;
  return 0;
}

// -1 behind, 0 on, +1 in front, given the sign of eval() behind.
inline int side(const Hyperplane& h, int behind_sign, const Vec& p) {
  const int s = sign(eval(h, p));
  if (s == 0) return 0;
  return s == behind_sign ? -1 : 1;
}

// ---- rays ---------------------------------------------------------------------------------------

// Where the line v + t d meets the affine hull of the (D-1)-simplex f: v + t d = sum lambda_i f_i,
// sum lambda_i = 1. `parallel` when the line does not meet it in one point.
struct LineFace {
  bool parallel = true;
  Q t;
  Vec lambda;
};

inline LineFace line_face(const Vec& v, const Vec& d, const std::vector<Vec>& f) {
  const std::size_t dim = v.size();
  Mat a(dim + 1, Vec(dim + 1));
  Vec b(dim + 1);
  for (std::size_t k = 0; k < dim; ++k) {
    for (std::size_t i = 0; i < dim; ++i) a[k][i] = f[i][k];
    a[k][dim] = -d[k];
    b[k] = v[k];
  }
  for (std::size_t i = 0; i < dim; ++i) a[dim][i] = 1;
  a[dim][dim] = 0;
  b[dim] = 1;
  LineFace r;
  const auto x = solve(a, b);
  if (!x) return r;
  r.parallel = false;
  r.lambda.assign(x->begin(), x->begin() + static_cast<std::ptrdiff_t>(dim));
  r.t = (*x)[dim];
  return r;
}

inline Q ray_delta() { return pow2(-100); }

// Plane sweep: d = -(e_1 + delta e_2 + delta^2 e_3 + ...).
inline Vec plane_direction(std::size_t dim, const Q& delta) {
  Vec d(dim);
  Q power(1);
  for (std::size_t k = 0; k < dim; ++k) {
    d[k] = -power;
    power *= delta;
  }
  return d;
}

// Sphere sweep: d = (Delta_0 - v) + delta (Delta_1 - v) + delta^2 (Delta_2 - v) + ...
inline Vec sphere_direction(const Vec& v, const std::vector<Vec>& seed, const Q& delta) {
  Vec d(v.size(), Q(0));
  Q power(1);
  for (const Vec& s : seed) {
    d = add(d, scale(power, sub(s, v)));
    power *= delta;
  }
  return d;
}

// ---- occlusion ----------------------------------------------------------------------------------

// p and q strictly on opposite sides of t's hyperplane, and the crossing point of segment pq lies in
// the closed simplex t.
inline bool occludes(const std::vector<Vec>& t, const Vec& p, const Vec& q) {
  const auto h = hyperplane_through(t);
  if (!h) return false;
  const int sp = sign(eval(*h, p)), sq = sign(eval(*h, q));
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const LineFace x = line_face(p, sub(q, p), t);
  if (x.parallel) throw std::logic_error("occludes reference: crossing segment parallel to face");
  return std::all_of(x.lambda.begin(), x.lambda.end(), [](const Q& l) { return sgn(l) >= 0; });
}

// ---- rotary order around a ridge ----------------------------------------------------------------

// y minus its components along the mutually orthogonal vectors `basis` (unnormalised Gram-Schmidt).
inline Vec project_out(Vec y, const std::vector<Vec>& basis) {
  for (const Vec& u : basis) y = sub(y, scale(dot(y, u) / dot(u, u), u));
  return y;
}

// The ridge r_0..r_{D-2} (D-1 points in R^D): an orthogonal basis of its direction space, and the
// projection of points onto the 2-plane orthogonal to it, relative to r_0.
class RidgeFrame {
 public:
  explicit RidgeFrame(const std::vector<Vec>& ridge) : ridge_(ridge) {
    for (std::size_t i = 1; i < ridge.size(); ++i) {
      const Vec u = project_out(sub(ridge[i], ridge[0]), basis_);
      if (is_zero(u)) throw std::invalid_argument("RidgeFrame: degenerate ridge");
      basis_.push_back(u);
    }
  }
  // Component of x - r_0 orthogonal to the ridge; zero iff x is in the ridge's affine hull.
  Vec normal_part(const Vec& x) const { return project_out(sub(x, ridge_[0]), basis_); }
  const std::vector<Vec>& ridge() const { return ridge_; }
  const std::vector<Vec>& basis() const { return basis_; }

 private:
  std::vector<Vec> ridge_;
  std::vector<Vec> basis_;
};

// Angles around the ridge measured from the half-hyperplane of `ref`, turning so that points with
// orient(ridge, ref, x) > 0 come in the first half-turn. key() gives (half, coordinates), where half
// is 0 (angle 0), 1 (open first half-turn), 2 (angle pi), 3 (open second half-turn).
class RotaryReference {
 public:
  RotaryReference(const RidgeFrame& frame, const Vec& ref) : frame_(frame) {
    w1_ = frame.normal_part(ref);
    if (is_zero(w1_)) throw std::invalid_argument("RotaryReference: ref in the ridge's hull");
    std::vector<Vec> span = frame.basis();
    span.push_back(w1_);
    const std::size_t dim = ref.size();
    for (std::size_t k = 0; k < dim && w2_.empty(); ++k) {
      Vec e(dim, Q(0));
      e[k] = 1;
      Vec y = project_out(e, span);
      if (!is_zero(y)) w2_ = y;
    }
    // Orient w2 so that orient(ridge, ref, r_0 + w2) > 0.
    std::vector<Vec> pts = frame.ridge();
    pts.push_back(ref);
    pts.push_back(add(frame.ridge()[0], w2_));
    const int o = orient(pts);
    if (o == 0) throw std::logic_error("RotaryReference: w2 not transverse");
    if (o < 0) w2_ = scale(Q(-1), w2_);
  }
  struct Key {
    int half;
    Q a1, a2;
  };
  Key key(const Vec& x) const {
    const Vec y = sub(x, frame_.ridge()[0]);
    Key k{0, dot(y, w1_), dot(y, w2_)};
    if (sgn(k.a1) == 0 && sgn(k.a2) == 0) throw std::invalid_argument("RotaryReference: apex in the ridge's hull");
    if (sgn(k.a2) > 0)
      k.half = 1;
    else if (sgn(k.a2) < 0)
      k.half = 3;
    else
      k.half = sgn(k.a1) > 0 ? 0 : 2;
    return k;
  }
  // -1 when a comes first, 0 at equal angles, +1 when b comes first.
  int compare(const Vec& a, const Vec& b) const {
    const Key ka = key(a), kb = key(b);
    if (ka.half != kb.half) return ka.half < kb.half ? -1 : 1;
    if (ka.half == 0 || ka.half == 2) return 0;
    const Q cross = ka.a1 * kb.a2 - ka.a2 * kb.a1;  // > 0: b is counterclockwise of a
    return -sign(cross);
  }

 private:
  const RidgeFrame& frame_;
  Vec w1_, w2_;
};

// a and b in one hyperplane with the ridge: on the same side of the ridge within it?
inline bool same_side_of_ridge(const RidgeFrame& frame, const Vec& a, const Vec& b) {
  return sign(dot(frame.normal_part(a), frame.normal_part(b))) > 0;
}

}  // namespace sweepcdt::ref
