// `halfspace generate`: writes a synthetic surface (self-affine random, or a
// built-in sphere, cylinder, wavy or flat surface) as an HDF5 height map that
// `halfspace solve --height-map` reads directly.
#pragma once

#include "command.hpp"

namespace halfspace::app {

// Registers `generate` on the program's parser.
Command add_generate_command(CLI::App& program);

}  // namespace halfspace::app
