// Whether a dataset's data are stored in its own file. An external raw-data
// file or a virtual dataset names other files, which halfspace has no
// business reading (a crafted one could point at /dev/zero or at any file),
// and a dataset never written holds only a fill value, however large it
// claims to be: a few hundred bytes could make a reader allocate and fill
// gigabytes.
#pragma once

#include <hdf5.h>

#include <optional>
#include <string>

namespace halfspace::io::detail {

// What keeps the dataset's data from being read from this file ("the
// dataset is virtual ..."), or nothing.
std::optional<std::string> unstored_data_problem(hid_t dataset);

}  // namespace halfspace::io::detail
