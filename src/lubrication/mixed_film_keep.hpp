// What a mixed film's Newton solves keep from one to the next through one
// solve_mixed_film call or one Stribeck sweep: each grid's dry contact
// (dry_contact_memo.hpp) and the storage of the GMRES basis
// (restarted_gmres.hpp), both the same for solve after solve on a grid.
// Private to the library.
#pragma once

#include "dry_contact_memo.hpp"
#include "restarted_gmres.hpp"

namespace halfspace::lubrication::detail {

struct MixedFilmKeep {
  DryContactMemo dry;
  ArnoldiStorage arnoldi;
};

}  // namespace halfspace::lubrication::detail
