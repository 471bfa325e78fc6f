// Halo rows of a film on slabs for the serial cavitation sweeps. Which
// sweep's values a halo row must hold follows from the serial order: the
// serial sweep runs along y (up when the entrainment's y component is >= 0,
// down otherwise), so a neighbour's row that the serial sweep passes before
// this process's rows holds this sweep's values, the other the previous
// sweep's. Each process sends its two boundary rows after every sweep (and
// once at the start), and reads them in order (MPI keeps the order of the
// messages between two processes with one tag), so that the halo holds
// exactly what the serial sweep reads. Sends are non-blocking: a process
// sends to its neighbour before it receives from it, which blocking sends
// of long rows would turn into a deadlock.
#include "halfspace/mpi/slab_film_rows.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "halfspace/error.hpp"
#include "halfspace/mpi/agreement.hpp"

namespace halfspace::mpi {

namespace {

// Tags by the halo they fill: the sender's last row fills the receiver's
// low halo (row below), its first row the receiver's high halo.
constexpr int kFillsLowHalo = 41;
constexpr int kFillsHighHalo = 42;

struct StencilRows {
  std::size_t first = 0;  // the stencil's first row, as a row of the whole grid (mod ny)
  std::size_t count = 0;
  bool low_halo = false;
  bool high_halo = false;
};

StencilRows stencil_rows(const Grid& whole, const lubrication::FlowConditions& conditions, const SlabLayout& slab,
                         int processes) {
  StencilRows rows;
  if (processes == 1) {
    rows.count = whole.ny();
    return rows;
  }
  const bool periodic = conditions.boundary.y == lubrication::AxisBoundary::periodic;
  rows.low_halo = slab.first_row > 0 || periodic;
  rows.high_halo = slab.first_row + slab.rows < whole.ny() || periodic;
  rows.first = rows.low_halo ? (slab.first_row + whole.ny() - 1) % whole.ny() : slab.first_row;
  rows.count = slab.rows + (rows.low_halo ? 1 : 0) + (rows.high_halo ? 1 : 0);
  return rows;
}

void require_rows(const Grid& whole, const SlabLayout& slab, const MpiCommunicator& comm) {
  run_agreed(comm, [&] {
    if (whole.dimension() != 2) {
      throw InputError(fmt::format("the film on slabs needs a 2D grid, not {}", whole.shape_string()));
    }
  });
  const double fewest = comm.min(static_cast<double>(slab.rows));
  if (fewest < 1.0) {
    throw InputError(
        fmt::format("the {} film leaves a process without rows on {} processes (slabs of up to {} "
                    "rows): each needs at least one row; use fewer processes",
                    whole.shape_string(), comm.size(), comm.max(static_cast<double>(slab.rows))));
  }
  // One row at an edge of a free film leaves a stencil of two rows, both
  // fixed: no grid the Reynolds stencil holds (the film's shear refused it
  // on that process alone, and the others waited for it).
  if (fewest < 2.0) {
    throw InputError(
        fmt::format("the {} film on {} processes leaves a process with 1 row: each needs at least 2; "
                    "use fewer processes",
                    whole.shape_string(), comm.size()));
  }
}

}  // namespace

SlabFilmRows::SlabFilmRows(const Grid& whole, const lubrication::FlowConditions& conditions, const SlabLayout& slab,
                           const MpiCommunicator& comm)
    : whole_((require_rows(whole, slab, comm), whole)),
      whole_boundary_(conditions.boundary),
      comm_(comm),
      stencil_grid_(whole),
      stencil_conditions_(conditions) {
  const StencilRows rows = stencil_rows(whole, conditions, slab, comm.size());
  first_whole_row_ = rows.first;
  own_first_ = rows.low_halo ? 1 : 0;
  own_rows_ = slab.rows;
  if (comm.size() == 1) return;  // the whole film: the serial stencil, nothing to exchange
  stencil_grid_ = Grid::plane(whole.nx(), rows.count, whole.dx(), whole.dy(), whole.boundary());
  stencil_conditions_.boundary.y = lubrication::AxisBoundary::fixed_pressure;
  const bool upward = conditions.entrainment_velocity[1] >= 0.0;
  const std::size_t first = slab.first_row;
  const std::size_t end = slab.first_row + slab.rows;
  const std::size_t ny = whole.ny();
  const int rank = comm.rank();
  const int processes = comm.size();
  const auto make = [&](std::size_t neighbour_row, int neighbour, std::size_t halo_row, std::size_t sent_row,
                        int receive_tag, int send_tag) {
    Link link;
    link.rank = neighbour;
    link.halo_row = halo_row;
    link.sent_row = sent_row;
    link.receive_tag = receive_tag;
    link.send_tag = send_tag;
    link.current = upward ? neighbour_row < first : neighbour_row >= end;
    link.in.resize(2 * whole.nx());
    link.out.resize(2 * whole.nx());
    links_.push_back(std::move(link));
  };
  if (rows.low_halo) {
    make(first > 0 ? first - 1 : ny - 1, (rank + processes - 1) % processes, 0, own_first_, kFillsLowHalo,
         kFillsHighHalo);
  }
  if (rows.high_halo) {
    make(end < ny ? end : 0, (rank + 1) % processes, rows.count - 1, own_first_ + own_rows_ - 1, kFillsHighHalo,
         kFillsLowHalo);
  }
}

SlabFilmRows::~SlabFilmRows() {
  for (Link& link : links_) MPI_Wait(&link.request, MPI_STATUS_IGNORE);
}

Eigen::ArrayXd SlabFilmRows::stencil_field(std::span<const double> rows) const {
  const std::size_t nx = whole_.nx();
  Eigen::ArrayXd field(static_cast<Eigen::Index>(stencil_grid_.size()));
  std::copy(rows.begin(), rows.end(), field.data() + own_first_ * nx);
  // All sends first: on two processes both links join the same pair.
  std::vector<MPI_Request> requests(links_.size(), MPI_REQUEST_NULL);
  for (std::size_t l = 0; l < links_.size(); ++l) {
    const Link& link = links_[l];
    check(MPI_Isend(field.data() + link.sent_row * nx, static_cast<int>(nx), MPI_DOUBLE, link.rank, link.send_tag,
                    comm_.get(), &requests[l]),
          "MPI_Isend");
  }
  for (const Link& link : links_) {
    check(MPI_Recv(field.data() + link.halo_row * nx, static_cast<int>(nx), MPI_DOUBLE, link.rank, link.receive_tag,
                   comm_.get(), MPI_STATUS_IGNORE),
          "MPI_Recv");
  }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  return field;
}

void SlabFilmRows::send(Link& link, const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) const {
  const std::size_t nx = whole_.nx();
  check(MPI_Wait(&link.request, MPI_STATUS_IGNORE), "MPI_Wait");
  std::copy_n(pressure.data() + link.sent_row * nx, nx, link.out.data());
  std::copy_n(fluid_fraction.data() + link.sent_row * nx, nx, link.out.data() + nx);
  check(MPI_Isend(link.out.data(), static_cast<int>(2 * nx), MPI_DOUBLE, link.rank, link.send_tag, comm_.get(),
                  &link.request),
        "MPI_Isend");
}

void SlabFilmRows::receive_until(Link& link, long sweep, Eigen::ArrayXd& pressure,
                                 Eigen::ArrayXd& fluid_fraction) const {
  const std::size_t nx = whole_.nx();
  while (link.received < sweep) {
    check(MPI_Recv(link.in.data(), static_cast<int>(2 * nx), MPI_DOUBLE, link.rank, link.receive_tag, comm_.get(),
                   MPI_STATUS_IGNORE),
          "MPI_Recv");
    ++link.received;
    std::copy_n(link.in.data(), nx, pressure.data() + link.halo_row * nx);
    std::copy_n(link.in.data() + nx, nx, fluid_fraction.data() + link.halo_row * nx);
  }
}

bool SlabFilmRows::fixed_in_whole(std::size_t k) const {
  const std::size_t nx = whole_.nx();
  const std::size_t i = k % nx;
  const std::size_t j = (first_whole_row_ + k / nx) % whole_.ny();
  const bool x_edge = whole_boundary_.x == lubrication::AxisBoundary::fixed_pressure && (i == 0 || i + 1 == nx);
  const bool y_edge =
      whole_boundary_.y == lubrication::AxisBoundary::fixed_pressure && (j == 0 || j + 1 == whole_.ny());
  return x_edge || y_edge;
}

void SlabFilmRows::start(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) {
  // Each solve (a load search makes several) counts its sweeps from 0; the
  // previous solve left no message unread (it stopped after a check).
  sweep_ = 0;
  for (Link& link : links_) link.received = -1;
  for (Link& link : links_) send(link, pressure, fluid_fraction);
}

void SlabFilmRows::before_sweep(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) {
  ++sweep_;
  for (Link& link : links_) receive_until(link, link.current ? sweep_ : sweep_ - 1, pressure, fluid_fraction);
}

void SlabFilmRows::after_sweep(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) {
  for (Link& link : links_) send(link, pressure, fluid_fraction);
}

void SlabFilmRows::complete(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) {
  for (Link& link : links_) receive_until(link, sweep_, pressure, fluid_fraction);
}

double SlabFilmRows::max(double value) const {
  return comm_.max(value);
}

bool SlabFilmRows::all(bool value) const {
  return comm_.min(value ? 1.0 : 0.0) > 0.5;
}

}  // namespace halfspace::mpi
