# Installs the built tree to a fresh prefix, then configures, builds and runs
# the consumer project beside this file against it, as a user would:
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DCXX_COMPILER=...
#         [-DCOMPILER_LAUNCHER=...] -P run_package_test.cmake
# Fails when a step fails, or when the installed package files name the
# source or build tree (the package must stand on its own).
foreach(required BUILD_DIR SOURCE_DIR WORK_DIR CXX_COMPILER)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run_package_test.cmake: -D${required}=... is missing")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc})")
  endif()
endfunction()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${WORK_DIR}")

run_step("cmake --install ${BUILD_DIR}" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")

# The umbrella header is installed, the engine's internals are not.
foreach(header halfspace/halfspace.hpp halfspace/solvers/solve_result.hpp)
  if(NOT EXISTS "${prefix}/include/${header}")
    message(FATAL_ERROR "the public header ${header} is not installed")
  endif()
endforeach()
foreach(internal halfspace/fft/real_fft.hpp halfspace/linalg/parallel.hpp halfspace/checked_size.hpp
                 halfspace/solvers/deflation_schedule.hpp halfspace/solvers/grid_transfer.hpp
                 halfspace/solvers/level_transfer.hpp halfspace/mpi)
  if(EXISTS "${prefix}/include/${internal}")
    message(FATAL_ERROR "the internal ${internal} is installed: only what halfspace/halfspace.hpp reaches should be")
  endif()
endforeach()

file(GLOB package_files "${prefix}/lib*/cmake/halfspace/*.cmake")
if(NOT package_files)
  message(FATAL_ERROR "no CMake package files under ${prefix}/lib*/cmake/halfspace")
endif()
get_filename_component(project_root "${SOURCE_DIR}/../.." ABSOLUTE)
foreach(file ${package_files})
  file(READ "${file}" text)
  foreach(tree "${project_root}" "${BUILD_DIR}")
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file} refers to ${tree}: the installed package must not name the build or source tree")
    endif()
  endforeach()
endforeach()

set(launcher_option "")
if(COMPILER_LAUNCHER)
  set(launcher_option "-DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER}")
endif()
run_step("configuring the consumer" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${consumer_build}"
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
  ${launcher_option})
# The package found must be the one just installed, not another on the system.
file(STRINGS "${consumer_build}/CMakeCache.txt" found_dir REGEX "^halfspace_DIR:")
string(REGEX REPLACE "^halfspace_DIR:[A-Z]*=" "" found_dir "${found_dir}")
file(REAL_PATH "${found_dir}" found_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${found_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "the consumer found halfspace in ${found_dir}, not under ${real_prefix}")
endif()
run_step("building the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}")
run_step("the consumer's Hertz check" "${consumer_build}/hertz_consumer")
