# How reebkit installs (docs/install.md):
#   cmake --install build --prefix P   the `reeb` command, the stage libraries,
#                                      the public headers, the CMake package,
#                                      a pkg-config file, the docs and LICENSE
#   cpack -G DEB (in build/)           reebkit_<version>_<arch>.deb (the command,
#                                      docs) and reebkit-dev_... (the rest)
# Two components: `runtime` (what a cluster node needs) and `dev` (what a
# program built on the library needs).
include(CMakePackageConfigHelpers)

set(REEBKIT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/reebkit)
get_property(reebkit_stages GLOBAL PROPERTY REEBKIT_STAGES)
list(TRANSFORM reebkit_stages PREPEND reebkit_ OUTPUT_VARIABLE reebkit_stage_targets)

install(TARGETS reeb RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(FILES LICENSE README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)

# The library as it is built: one static library per stage (reebkit::<stage>)
# and reebkit::reebkit linking them all. Their own dependencies are found
# again by reebkitConfig.cmake (find_dependency).
install(TARGETS reebkit ${reebkit_stage_targets} EXPORT reebkitTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
foreach(header IN LISTS REEBKIT_PUBLIC_HEADERS)
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES lib/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${folder} COMPONENT dev)
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/reebkit/core/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/reebkit/core COMPONENT dev)

install(EXPORT reebkitTargets NAMESPACE reebkit:: DESTINATION ${REEBKIT_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(cmake/reebkitConfig.cmake.in ${PROJECT_BINARY_DIR}/reebkitConfig.cmake
  INSTALL_DESTINATION ${REEBKIT_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/reebkitConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/reebkitConfig.cmake ${PROJECT_BINARY_DIR}/reebkitConfigVersion.cmake
  DESTINATION ${REEBKIT_CMAKE_DIR} COMPONENT dev)

# pkg-config: the stage libraries, last stage first, then what they link
# (the same libraries the CMake package finds).
list(REVERSE reebkit_stages)
list(TRANSFORM reebkit_stages PREPEND -lreebkit_ OUTPUT_VARIABLE REEBKIT_PC_LIBS)
list(JOIN REEBKIT_PC_LIBS " " REEBKIT_PC_LIBS)
file(RELATIVE_PATH REEBKIT_PC_PREFIX /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p/)  # relocatable: from ${pcfiledir}
string(REGEX REPLACE "/$" "" REEBKIT_PC_PREFIX "${REEBKIT_PC_PREFIX}")
configure_file(cmake/reebkit.pc.in ${PROJECT_BINARY_DIR}/reebkit.pc.configured @ONLY)
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/reebkit.pc INPUT ${PROJECT_BINARY_DIR}/reebkit.pc.configured)
install(FILES ${PROJECT_BINARY_DIR}/reebkit.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

# The Debian packages. reebkit's dependencies are those dpkg-shlibdeps finds
# in `reeb` (HDF5, FLANN, Boost.Program_options, meshoptimizer, OpenMP, Open
# MPI when built with it); reebkit-dev's are the -dev packages the CMake
# package and the pkg-config file find again.
set(CPACK_PACKAGE_NAME reebkit)
set(CPACK_PACKAGE_VENDOR "reebkit")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "reebkit developers")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME reebkit)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "python3, python3-matplotlib")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME reebkit-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
  "reebkit (= ${PROJECT_VERSION}), libeigen3-dev, libhdf5-dev, libflann-dev, liblz4-dev, libmeshoptimizer-dev, g++")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "the reeb command: index, query and evaluate 3D mesh collections")
set(CPACK_COMPONENT_DEV_DESCRIPTION "the reebkit C++ library: static libraries, headers, CMake package, pkg-config file")
include(CPack)
