# Finds the numerics component of Siconos (Debian: libsiconos-numerics-dev),
# the LCP solvers halfspace uses for Lemke pivoting. Defines
# SiconosNumerics::numerics. Siconos's own CMake package is not used: it
# checks for every Siconos component (kernel, mechanics, ...), which the
# numerics package alone does not install.
find_path(SiconosNumerics_INCLUDE_DIR NAMES LCP_Solvers.h PATH_SUFFIXES siconos/numerics)
find_path(SiconosNumerics_CONFIG_INCLUDE_DIR NAMES SiconosConfig.h PATH_SUFFIXES siconos)
find_library(SiconosNumerics_LIBRARY NAMES siconos_numerics)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SiconosNumerics
  REQUIRED_VARS SiconosNumerics_LIBRARY SiconosNumerics_INCLUDE_DIR SiconosNumerics_CONFIG_INCLUDE_DIR)

if(SiconosNumerics_FOUND AND NOT TARGET SiconosNumerics::numerics)
  add_library(SiconosNumerics::numerics UNKNOWN IMPORTED)
  set_target_properties(SiconosNumerics::numerics PROPERTIES
    IMPORTED_LOCATION "${SiconosNumerics_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SiconosNumerics_INCLUDE_DIR};${SiconosNumerics_CONFIG_INCLUDE_DIR}")
endif()
mark_as_advanced(SiconosNumerics_INCLUDE_DIR SiconosNumerics_CONFIG_INCLUDE_DIR SiconosNumerics_LIBRARY)
