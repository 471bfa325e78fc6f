// The rigid Reynolds film with mass-conserving cavitation on slabs of rows:
// each process sweeps its rows of the 2D film with the serial solver
// (cavitation_solver.hpp) on a stencil over its rows and one halo row each
// side, which this object exchanges with the neighbouring processes between
// the sweeps (lubrication/film_rows.hpp says which sweep's values), and the
// convergence measures are reduced over the communicator. The iterates are
// the serial ones, so the solution equals the serial program's (to the last
// bit, tests/mpi/slab_film_test.cpp). A sweep reads the row that the
// process before it has just swept, so the processes follow each other as
// a wavefront along the entrainment's y component: with fixed pressures on
// the y edges they sweep at once, one sweep apart; on a y-periodic film
// each sweep waits for the wrap-around row, so the processes take turns.
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/film_rows.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fft.hpp"

namespace halfspace::mpi {

class SlabFilmRows final : public lubrication::FilmRows {
 public:
  // This process's rows `slab` of the 2D film on `whole` with `conditions`.
  // Collective; throws InputError (on every process alike) for a 1D grid or
  // when some process holds fewer than 2 rows. `comm` must outlive this
  // object.
  SlabFilmRows(const Grid& whole, const lubrication::FlowConditions& conditions, const SlabLayout& slab,
               const MpiCommunicator& comm);
  ~SlabFilmRows() override;
  SlabFilmRows(const SlabFilmRows&) = delete;
  SlabFilmRows& operator=(const SlabFilmRows&) = delete;

  const Grid& stencil_grid() const override { return stencil_grid_; }
  const lubrication::FlowConditions& stencil_conditions() const override { return stencil_conditions_; }
  Eigen::ArrayXd stencil_field(std::span<const double> rows) const override;
  std::size_t first_own_node() const override { return own_first_ * whole_.nx(); }
  std::size_t own_nodes() const override { return own_rows_ * whole_.nx(); }
  bool fixed_in_whole(std::size_t k) const override;
  void sum(std::span<double> values) const override { comm_.sum(values); }
  double min(double value) const override { return comm_.min(value); }

  const Grid& whole_grid() const override { return whole_; }
  void start(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) override;
  void before_sweep(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) override;
  void after_sweep(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) override;
  void complete(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) override;
  double max(double value) const override;
  bool all(bool value) const override;

 private:
  // One neighbour: the halo row it fills and the boundary row it is sent.
  struct Link {
    int rank = -1;
    std::size_t halo_row = 0;  // rows of the stencil
    std::size_t sent_row = 0;
    int receive_tag = 0;
    int send_tag = 0;
    bool current = false;  // the halo holds this sweep's values (else the previous sweep's)
    long received = -1;    // the last sweep whose row has arrived
    std::vector<double> in;
    std::vector<double> out;
    MPI_Request request = MPI_REQUEST_NULL;
  };

  void receive_until(Link& link, long sweep, Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) const;
  void send(Link& link, const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) const;

  Grid whole_;
  lubrication::FlowBoundary whole_boundary_;
  const MpiCommunicator& comm_;
  std::size_t first_whole_row_ = 0;  // the stencil's first row, as a row of the whole film
  std::size_t own_first_ = 0;        // the first of this process's rows in the stencil
  std::size_t own_rows_ = 0;
  Grid stencil_grid_;
  lubrication::FlowConditions stencil_conditions_;
  std::vector<Link> links_;
  long sweep_ = 0;
};

}  // namespace halfspace::mpi
