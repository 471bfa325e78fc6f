# Finds FFTW 3 in double and single precision and their OpenMP threading
# libraries (Debian's libfftw3-dev carries both precisions).
# Defines FFTW3::fftw3, FFTW3::fftw3_omp, FFTW3::fftw3f and FFTW3::fftw3f_omp
# (Debian ships no CMake config for FFTW).
find_path(FFTW3_INCLUDE_DIR fftw3.h)
find_library(FFTW3_LIBRARY NAMES fftw3)
find_library(FFTW3_OMP_LIBRARY NAMES fftw3_omp)
find_library(FFTW3F_LIBRARY NAMES fftw3f)
find_library(FFTW3F_OMP_LIBRARY NAMES fftw3f_omp)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FFTW3
  REQUIRED_VARS FFTW3_LIBRARY FFTW3_OMP_LIBRARY FFTW3F_LIBRARY FFTW3F_OMP_LIBRARY FFTW3_INCLUDE_DIR)

if(FFTW3_FOUND AND NOT TARGET FFTW3::fftw3)
  add_library(FFTW3::fftw3 UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3 PROPERTIES
    IMPORTED_LOCATION "${FFTW3_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${FFTW3_INCLUDE_DIR}")
  add_library(FFTW3::fftw3_omp UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3_omp PROPERTIES
    IMPORTED_LOCATION "${FFTW3_OMP_LIBRARY}"
    INTERFACE_LINK_LIBRARIES FFTW3::fftw3)
  add_library(FFTW3::fftw3f UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3f PROPERTIES
    IMPORTED_LOCATION "${FFTW3F_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${FFTW3_INCLUDE_DIR}")
  add_library(FFTW3::fftw3f_omp UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3f_omp PROPERTIES
    IMPORTED_LOCATION "${FFTW3F_OMP_LIBRARY}"
    INTERFACE_LINK_LIBRARIES FFTW3::fftw3f)
endif()
mark_as_advanced(FFTW3_INCLUDE_DIR FFTW3_LIBRARY FFTW3_OMP_LIBRARY FFTW3F_LIBRARY FFTW3F_OMP_LIBRARY)

# FFTW's MPI interface (libfftw3-mpi-dev), for the HALFSPACE_MPI build only:
# FFTW3::fftw3_mpi when the library is found. Link MPI itself separately.
find_library(FFTW3_MPI_LIBRARY NAMES fftw3_mpi)
if(FFTW3_FOUND AND FFTW3_MPI_LIBRARY AND NOT TARGET FFTW3::fftw3_mpi)
  add_library(FFTW3::fftw3_mpi UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3_mpi PROPERTIES
    IMPORTED_LOCATION "${FFTW3_MPI_LIBRARY}"
    INTERFACE_LINK_LIBRARIES FFTW3::fftw3)
endif()
mark_as_advanced(FFTW3_MPI_LIBRARY)
