// The EHL GMRES preconditioners (film_preconditioner.hpp): the sparse LU
// here, the multigrid in film_multigrid.cpp.
#include "film_preconditioner.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>

#include "film_multigrid.hpp"

namespace halfspace::lubrication::detail {

void CsrMatrix::clear() {
  rows = 0;
  start.assign(1, 0);
  column.clear();
  value.clear();
}

void append_summed(std::vector<std::pair<int, double>>& entries, std::vector<int>& column, std::vector<double>& value) {
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t e = 0; e < entries.size(); ++e) {
    if (e > 0 && entries[e].first == entries[e - 1].first) {
      value.back() += entries[e].second;
    } else {
      column.push_back(entries[e].first);
      value.push_back(entries[e].second);
    }
  }
}

void CsrMatrix::append_row(std::vector<std::pair<int, double>>& entries) {
  append_summed(entries, column, value);
  entries.clear();
  ++rows;
  start.push_back(static_cast<int>(column.size()));
}

namespace {

// SparseLU's fill relative to the matrix's entries, a measured allowance
// (64^2 to 256^2 point contacts with COLAMD; docs/development-log.md).
constexpr double kFillAllowance = 12.0;

// Eigen's supernodal LU with the COLAMD ordering; the pattern is the same
// at every Newton step (every entry written, zero or not), so it is
// analysed once.
class SparseLuPreconditioner final : public FilmPreconditioner {
 public:
  bool factorise(const CsrMatrix& matrix, std::string& message) override {
    const auto n = static_cast<Eigen::Index>(matrix.rows);
    const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> rows(
        n, n, static_cast<Eigen::Index>(matrix.entries()), matrix.start.data(), matrix.column.data(),
        matrix.value.data());
    sparse_ = rows;
    if (!analysed_) {
      lu_.analyzePattern(sparse_);
      analysed_ = true;
    }
    lu_.factorize(sparse_);
    if (lu_.info() != Eigen::Success) {
      message = fmt::format("the film preconditioner's sparse LU failed: {}", lu_.lastErrorMessage());
      return false;
    }
    return true;
  }

  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) override { out = lu_.solve(in); }

 private:
  Eigen::SparseMatrix<double> sparse_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
  bool analysed_ = false;
};

}  // namespace

std::unique_ptr<FilmPreconditioner> make_film_preconditioner(KrylovPreconditioner kind, const Grid& grid,
                                                             int line_axis) {
  if (kind == KrylovPreconditioner::sparse_lu) return std::make_unique<SparseLuPreconditioner>();
  return std::make_unique<FilmMultigrid>(grid, line_axis, true);
}

double film_preconditioner_bytes_per_node(KrylovPreconditioner kind, double row_entries) {
  if (kind == KrylovPreconditioner::sparse_lu) return row_entries * 12.0 * (1.0 + kFillAllowance);
  return FilmMultigrid::bytes_per_node(row_entries);
}

}  // namespace halfspace::lubrication::detail
