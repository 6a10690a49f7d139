# Every dependency comes from a Debian 12 package. A missing one stops the
# configure step and names the package to install.

macro(reebkit_require name package)
  find_package(${name} ${ARGN} QUIET)
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR
      "reebkit needs ${name}: install it with\n  sudo apt-get install ${package}\n"
      "(or run `bash tools/run test`, which installs every missing package)")
  endif()
endmacro()

reebkit_require(Eigen3 libeigen3-dev 3.3 NO_MODULE)
reebkit_require(OpenMP libomp-dev)
set(HDF5_PREFER_PARALLEL FALSE)
reebkit_require(HDF5 libhdf5-dev COMPONENTS C CXX)
reebkit_require(Boost libboost-program-options-dev COMPONENTS program_options)
reebkit_require(flann libflann-dev)
reebkit_require(meshoptimizer libmeshoptimizer-dev)
reebkit_require(Spectra libspectra-dev)
if(REEBKIT_BUILD_TESTS)
  reebkit_require(GTest libgtest-dev)
endif()
if(REEBKIT_BUILD_BENCH)
  reebkit_require(benchmark libbenchmark-dev)
endif()

# Warnings for reebkit's own targets (never global flags).
add_library(reebkit_warnings INTERFACE)
target_compile_options(reebkit_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<AND:$<BOOL:${REEBKIT_WARNINGS_AS_ERRORS}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>)
