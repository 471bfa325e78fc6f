# Finds ALGLIB (Debian: libalglib-dev), whose minqp dense interior-point
# solver runs the LCPquad formulation. Defines ALGLIB::alglib. Debian's
# ALGLIBConfig.cmake defines no target and reports success even when the
# library is missing, so halfspace uses this module instead.
# The include directory is the one holding libalglib/, so sources write
# <libalglib/optimization.h> and ALGLIB's generic header names (ap.h,
# statistics.h, ...) cannot shadow anything else.
find_path(ALGLIB_INCLUDE_DIR NAMES libalglib/optimization.h)
find_library(ALGLIB_LIBRARY NAMES alglib)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ALGLIB REQUIRED_VARS ALGLIB_LIBRARY ALGLIB_INCLUDE_DIR)

if(ALGLIB_FOUND AND NOT TARGET ALGLIB::alglib)
  add_library(ALGLIB::alglib UNKNOWN IMPORTED)
  set_target_properties(ALGLIB::alglib PROPERTIES
    IMPORTED_LOCATION "${ALGLIB_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${ALGLIB_INCLUDE_DIR}")
endif()
mark_as_advanced(ALGLIB_INCLUDE_DIR ALGLIB_LIBRARY)
