# Writes version.hpp with the current git hash. Run at every build (target
# halfspace_version) so that a rebuilt tree never reports the hash of its
# last configure; configure_file leaves the file alone when nothing changed,
# so an unchanged hash recompiles nothing.
#   cmake -DSOURCE_DIR=... -DOUTPUT=... -DPROJECT_VERSION=... -P write_version.cmake
execute_process(COMMAND git describe --always --dirty --abbrev=12
  WORKING_DIRECTORY "${SOURCE_DIR}"
  OUTPUT_VARIABLE HALFSPACE_GIT_HASH OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT HALFSPACE_GIT_HASH)
  set(HALFSPACE_GIT_HASH "unknown")
endif()
configure_file("${SOURCE_DIR}/cmake/version.hpp.in" "${OUTPUT}" @ONLY)
