// This process's rows of a film whose influence operator is spread over
// processes in slabs of rows (the distributed operators of mpi/), and the
// halo rows of its neighbours that the Reynolds stencil reaches: the
// Newton solve of the EHL film (elastic_film.cpp) runs on this stencil, so
// that one code serves one process (the whole grid, no halo, every
// reduction the identity) and many (each its slab, halos fetched through
// the operator's linalg::Communicator, sums and extremes reduced). The
// stencil's y edges are fixed-pressure edges of the stencil alone: the
// nodes solved are this process's, whose neighbours all lie in the
// stencil. Private to the library.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "film_preconditioner.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/lubrication/film_rows.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "restarted_gmres.hpp"

namespace halfspace::lubrication::detail {

class FilmSlab {
 public:
  // The film on `whole` with `conditions`, of which this process holds
  // `own_nodes` nodes (whole rows, in rank order over `comm`), with `halo`
  // rows of each neighbour. Collective. Throws InputError when the grid is
  // 1D and spread, or some process holds fewer than 2 rows (its rows are a
  // grid of their own) or fewer than `halo` (then the halo would reach past
  // its neighbour).
  FilmSlab(const Grid& whole, const FlowConditions& conditions, std::size_t own_nodes, const linalg::Communicator& comm,
           std::size_t halo);

  bool distributed() const { return comm_.size() > 1; }
  const linalg::Communicator& communicator() const { return comm_; }
  const Grid& whole_grid() const { return whole_; }
  // The stencil: this process's rows with the halo rows around them.
  const Grid& stencil_grid() const { return stencil_grid_; }
  const FlowConditions& stencil_conditions() const { return stencil_conditions_; }
  // This process's rows as a grid of their own (the whole grid on one
  // process): the preconditioner's.
  const Grid& own_grid() const { return own_grid_; }
  std::size_t stencil_nodes() const { return stencil_grid_.size(); }
  std::size_t own_first() const { return own_first_; }  // the stencil node of this process's first node
  std::size_t own_nodes() const { return own_nodes_; }
  std::size_t first_row() const { return first_row_; }  // this process's first row of the whole grid
  // The whole grid's node of a stencil node, and the stencil node of a
  // whole grid's node (kOutside if it is not in the stencil).
  std::size_t whole_node(std::size_t stencil_node) const;
  static constexpr std::size_t kOutside = static_cast<std::size_t>(-1);
  std::size_t stencil_node(std::size_t whole_node) const;

  // Fills the halo rows of a stencil field (stencil_nodes() values) from
  // the processes that own them (this process's own rows already in
  // place). Collective; nothing on one process.
  void exchange(double* field) const;

  // The stencil values of a field given on this process's nodes (`own`):
  // `own` itself on one process (the stencil is the own nodes), else
  // `stencil` (stencil_nodes() values) with `own` copied in and the halo
  // exchanged. Collective on several processes.
  const double* on_stencil(Eigen::Ref<const Eigen::VectorXd> own, Eigen::VectorXd& stencil) const;

  // The rows around this process's: `below` rows before its first and
  // `above` after its last (wrapped on a y-periodic film; each at most the
  // rows the others hold together), `width` values per node, into
  // `around`: the rows below, `own` (this process's rows), the rows above.
  // Collective (each process its own counts); on one process `own` alone.
  void rows_around(const double* own, std::size_t below, std::size_t above, std::size_t width, double* around) const;
  // The most rows below and above this process's that rows_around can take
  // (the film's edges, or on a y-periodic film the other processes' rows
  // shared between the two sides), up to `wanted` each.
  std::pair<std::size_t, std::size_t> rows_around_limits(std::size_t wanted) const;
  // The whole grid's row of a row of the rows around (`below` before
  // this process's first).
  std::size_t whole_row_around(std::size_t row, std::size_t below) const {
    return (first_row_ + whole_.ny() - below + row) % whole_.ny();
  }

  // The rows of a sparse matrix that a block of rows around this process's
  // holds (`below` rows before its first, `above` after its last, as
  // rows_around): `own` this process's rows (columns whole-grid nodes),
  // `block` the block's rows in the block's own columns (entries outside
  // the block dropped). `scratch` keeps the packed rows between calls.
  // Collective.
  struct RowScratch {
    std::vector<double> packed_own, packed_block;
    std::vector<std::pair<int, double>> row;
  };
  void gather_rows(const CsrMatrix& own, std::size_t below, std::size_t above, CsrMatrix& block,
                   RowScratch& scratch) const;

  // The contact's centre, the first node of the whole grid with the smallest
  // of `gap` (this process's nodes): its index among this process's nodes
  // if it holds it, else -1. Collective.
  Eigen::Index centre_node(const Eigen::ArrayXd& gap) const;

  // Reductions over the processes (the identity on one).
  double sum(double local) const;
  double max(double local) const { return comm_.max(local); }
  double min(double local) const { return comm_.min(local); }
  bool all(bool local) const { return comm_.min(local ? 1.0 : 0.0) > 0.5; }
  // The Euclidean norm of a vector of this process's entries followed by
  // `replicated` entries every process holds alike (h0): those counted
  // once. On one process Eigen's norm, unchanged.
  double norm(Eigen::Ref<const Eigen::VectorXd> v, Eigen::Index replicated) const;
  // The same inner product.
  double dot(Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b, Eigen::Index replicated) const;
  // How the GMRES solve of a Newton step reduces over the processes
  // (nothing on one process: Eigen's products, unchanged).
  KrylovDistribution krylov_distribution() const;

 private:
  void fetch(const double* field, std::size_t whole_first, std::size_t rows, double* into) const;
  // Whole rows [first, first + rows) of a field held `width` values per
  // node, own rows at `own`, into `into` (a range that may wrap past the
  // last row: two collective fetches, always both).
  void fetch_wrapping(const double* own, std::size_t first, std::size_t rows, std::size_t width, double* into) const;

  Grid whole_;
  bool periodic_y_ = false;
  const linalg::Communicator& comm_;
  std::size_t first_row_ = 0, own_rows_ = 0, own_first_ = 0, own_nodes_ = 0;
  std::size_t low_halo_ = 0, high_halo_ = 0;
  Grid stencil_grid_, own_grid_;
  FlowConditions stencil_conditions_;
};

// Runs `check` on every process of `comm`: where it throws InputError on
// some process (a memory check of its share), every process throws, that
// process with its message, the others naming it. Collective; on one
// process `check()`.
void agree_on_input(const linalg::Communicator& comm, const std::function<void()>& check);

// A slab seen as the film pipeline's FilmRows (film_rows.hpp), for what
// follows a Newton solve on slabs (the mixed film's shear, film_shear.hpp):
// stencil fields, this process's nodes and the reductions. The cavitation
// solver's sweeps do not run on it: their halo calls exchange the rows as
// they are, and fixed_in_whole throws std::logic_error.
class FilmSlabRows final : public FilmRows {
 public:
  explicit FilmSlabRows(const FilmSlab& slab) : slab_(slab) {}

  const Grid& whole_grid() const override { return slab_.whole_grid(); }
  void start(const Eigen::ArrayXd&, const Eigen::ArrayXd&) override {}
  void before_sweep(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) override {
    complete(pressure, fluid_fraction);
  }
  void after_sweep(const Eigen::ArrayXd&, const Eigen::ArrayXd&) override {}
  void complete(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) override;
  double max(double value) const override { return slab_.max(value); }
  bool all(bool value) const override { return slab_.all(value); }
  const Grid& stencil_grid() const override { return slab_.stencil_grid(); }
  const FlowConditions& stencil_conditions() const override { return slab_.stencil_conditions(); }
  Eigen::ArrayXd stencil_field(std::span<const double> rows) const override;
  std::size_t first_own_node() const override { return slab_.own_first(); }
  std::size_t own_nodes() const override { return slab_.own_nodes(); }
  bool fixed_in_whole(std::size_t k) const override;
  void sum(std::span<double> values) const override { slab_.communicator().sum(values); }
  double min(double value) const override { return slab_.min(value); }

 private:
  const FilmSlab& slab_;
};

}  // namespace halfspace::lubrication::detail
