// Least-squares detrending. The fit is done in centred, scaled coordinates
// u = (i - ic) / hx, v = (j - jc) / hy in [-1, 1], where the normal equations
// of the monomials up to degree 2 are well conditioned (condition number
// ~10^2), then refined once by fitting the residual again (iterative
// refinement, Golub & Van Loan 5.3.8), which recovers the accuracy of an
// orthogonal factorisation at the cost of a second pass and no N x 6 matrix.
#include "halfspace/surface/detrend.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "halfspace/error.hpp"

namespace halfspace::surface {
namespace {

constexpr int kMaxTerms = 6;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxTerms, 1>;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxTerms, kMaxTerms>;

struct Basis {
  int terms = 1;
  double ic = 0.0, jc = 0.0, hx = 1.0, hy = 1.0;  // centre and half-width, in cells

  // Monomials 1, u, v, u^2, u v, v^2 (2D) or 1, u, u^2 (1D), at point (j, i).
  void evaluate(std::size_t j, std::size_t i, bool two_d, double* phi) const {
    const double u = (static_cast<double>(i) - ic) / hx;
    const double v = (static_cast<double>(j) - jc) / hy;
    phi[0] = 1.0;
    if (terms == 1) return;
    phi[1] = u;
    if (two_d) {
      phi[2] = v;
      if (terms > 3) {
        phi[3] = u * u;
        phi[4] = u * v;
        phi[5] = v * v;
      }
    } else if (terms > 2) {
      phi[2] = u * u;
    }
  }
};

// What is fitted, in words: a plane is a line on a profile, a quadratic a parabola.
std::string_view surface_name(Detrend detrend, int dimension) {
  switch (detrend) {
    case Detrend::plane:
      return dimension == 1 ? "line" : "plane";
    case Detrend::curvature:
      return dimension == 1 ? "parabola" : "quadratic";
    default:
      return "mean";
  }
}

int term_count(Detrend detrend, int dimension) {
  switch (detrend) {
    case Detrend::mean:
      return 1;
    case Detrend::plane:
      return dimension == 1 ? 2 : 3;
    case Detrend::curvature:
      return dimension == 1 ? 3 : 6;
    case Detrend::none:
      break;
  }
  return 0;
}

// The rows a map's heights hold: all of them, or a process's slab.
struct Rows {
  std::size_t first = 0;
  std::size_t count = 0;
};

// Least-squares coefficients of `values` (a residual or the heights) over the
// valid points; the normal equations' sums are added over `comm`.
Vector fit(const HeightMap& map, const Eigen::ArrayXd& values, const Basis& basis, std::string_view name,
           std::size_t& used, Rows rows, const linalg::Communicator& comm) {
  const int p = basis.terms;
  Matrix normal = Matrix::Zero(p, p);
  Vector rhs = Vector::Zero(p);
  double phi[kMaxTerms];
  double points = 0.0;
  for (std::size_t r = 0; r < rows.count; ++r) {
    for (std::size_t i = 0; i < map.nx; ++i) {
      const std::size_t k = r * map.nx + i;
      if (!map.is_valid(k)) continue;
      basis.evaluate(rows.first + r, i, map.dimension == 2, phi);
      const double h = values[static_cast<Eigen::Index>(k)];
      for (int a = 0; a < p; ++a) {
        rhs[a] += phi[a] * h;
        for (int b = 0; b <= a; ++b) normal(a, b) += phi[a] * phi[b];
      }
      points += 1.0;
    }
  }
  if (comm.size() > 1) {
    double sums[kMaxTerms * kMaxTerms + kMaxTerms + 1];
    std::size_t n = 0;
    for (int a = 0; a < p; ++a) {
      sums[n++] = rhs[a];
      for (int b = 0; b <= a; ++b) sums[n++] = normal(a, b);
    }
    sums[n++] = points;
    comm.sum({sums, n});
    n = 0;
    for (int a = 0; a < p; ++a) {
      rhs[a] = sums[n++];
      for (int b = 0; b <= a; ++b) normal(a, b) = sums[n++];
    }
    points = sums[n];
  }
  used = static_cast<std::size_t>(points);
  normal = normal.selfadjointView<Eigen::Lower>();
  const Eigen::ColPivHouseholderQR<Matrix> qr(normal);
  if (qr.rank() < p) {
    throw InputError(
        fmt::format("height map {}: cannot fit the {}: its {} valid points do not determine {} "
                    "coefficients (they lie on a line or are too few)",
                    map.source, name, used, p));
  }
  return qr.solve(rhs);
}

void subtract(HeightMap& map, Eigen::ArrayXd& values, const Basis& basis, const Vector& c, Rows rows) {
  double phi[kMaxTerms];
  for (std::size_t r = 0; r < rows.count; ++r) {
    for (std::size_t i = 0; i < map.nx; ++i) {
      const std::size_t k = r * map.nx + i;
      if (!map.is_valid(k)) continue;
      basis.evaluate(rows.first + r, i, map.dimension == 2, phi);
      double surface = 0.0;
      for (int a = 0; a < basis.terms; ++a) surface += c[a] * phi[a];
      values[static_cast<Eigen::Index>(k)] -= surface;
    }
  }
}

// The removed surface in words: value at the centre and derivatives there,
// per metre when the spacing is known, else per cell.
std::string describe(const HeightMap& map, Detrend detrend, const Basis& basis, const Vector& c, std::size_t used) {
  const bool metric_x = map.dx > 0.0;
  const bool metric_y = map.dy > 0.0;
  const double sx = basis.hx * (metric_x ? map.dx : 1.0);  // length of u = 1
  const double sy = basis.hy * (metric_y ? map.dy : 1.0);
  const char* per_x = metric_x ? "" : " per cell";
  const char* per_y = metric_y ? "" : " per cell";
  std::string text =
      fmt::format("detrend {}: subtracted the least-squares {} over {} valid points: mean level {:.6g} m",
                  to_string(detrend), surface_name(detrend, map.dimension), used, c[0]);
  if (detrend == Detrend::mean) return text;
  if (detrend == Detrend::plane || detrend == Detrend::curvature) {
    text += fmt::format(", slope dh/dx = {:.6g}{}", c[1] / sx, per_x);
    if (map.dimension == 2) text += fmt::format(", dh/dy = {:.6g}{}", c[2] / sy, per_y);
  }
  if (detrend == Detrend::curvature) {
    if (map.dimension == 1) {
      text += fmt::format(", d2h/dx2 = {:.6g} {}", 2.0 * c[2] / (sx * sx), metric_x ? "1/m" : "m per cell^2");
    } else {
      text += fmt::format(", d2h/dx2 = {:.6g}, d2h/dxdy = {:.6g}, d2h/dy2 = {:.6g} (1/m{})", 2.0 * c[3] / (sx * sx),
                          c[4] / (sx * sy), 2.0 * c[5] / (sy * sy),
                          metric_x && metric_y ? "" : ", per cell where a spacing is unknown");
    }
  }
  return text + " at the map centre";
}

}  // namespace

std::string_view to_string(Detrend detrend) {
  switch (detrend) {
    case Detrend::none:
      return "none";
    case Detrend::mean:
      return "mean";
    case Detrend::plane:
      return "plane";
    case Detrend::curvature:
      return "curvature";
  }
  return "unknown";
}

Detrend parse_detrend(std::string_view text) {
  if (text == "none") return Detrend::none;
  if (text == "mean") return Detrend::mean;
  if (text == "plane" || text == "tilt") return Detrend::plane;
  if (text == "curvature" || text == "quadratic") return Detrend::curvature;
  throw InputError(fmt::format("detrend '{}' is unknown: use none, mean, plane (tilt) or curvature (quadratic)", text));
}

void detrend(HeightMap& map, Detrend detrend) {
  detrend_rows(map, detrend, 0, linalg::serial_communicator());
}

void detrend_rows(HeightMap& map, Detrend detrend, std::size_t first_row, const linalg::Communicator& comm) {
  if (detrend == Detrend::none) return;
  const Rows rows{first_row, static_cast<std::size_t>(map.heights.size()) / map.nx};
  Basis basis;
  basis.terms = term_count(detrend, map.dimension);
  basis.ic = 0.5 * static_cast<double>(map.nx - 1);
  basis.jc = 0.5 * static_cast<double>(map.ny - 1);
  basis.hx = std::max(basis.ic, 0.5);
  basis.hy = std::max(basis.jc, 0.5);

  std::size_t used = 0;
  Vector coefficients = fit(map, map.heights, basis, surface_name(detrend, map.dimension), used, rows, comm);
  if (used == 0) throw InputError(fmt::format("height map {}: no valid points to detrend", map.source));
  subtract(map, map.heights, basis, coefficients, rows);
  // One step of iterative refinement: the residual's own fit is the error of the first.
  const Vector correction = fit(map, map.heights, basis, surface_name(detrend, map.dimension), used, rows, comm);
  subtract(map, map.heights, basis, correction, rows);
  coefficients += correction;
  map.preparation.push_back(describe(map, detrend, basis, coefficients, used));
}

}  // namespace halfspace::surface
