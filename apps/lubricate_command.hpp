// The lubricate command: a height map's rigid Reynolds film with
// mass-conserving cavitation at a separation or a load, written to HDF5.
#pragma once

#include "command.hpp"

namespace halfspace::app {

Command add_lubricate_command(CLI::App& program);

}  // namespace halfspace::app
