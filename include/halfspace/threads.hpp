// Thread count for OpenMP loops and FFTW transforms, set together.
#pragma once

namespace halfspace {

// Sets the number of threads used by elementwise loops (OpenMP) and by FFT
// plans made afterwards (FFTW threads). Throws InputError if threads < 1.
void set_threads(int threads);

// The thread count currently in force.
int threads();

}  // namespace halfspace
