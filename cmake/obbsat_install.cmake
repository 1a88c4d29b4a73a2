# Installation: headers, static libraries, the obbsat program, a CMake package
# (find_package(obbsat)) and a pkg-config file.
#
# Installed targets, under the namespace obbsat::
#   obbsat::obbsat  the library (data model, dispatcher, batch API); links
#                   obbsat::ref and, as a static library, Threads
#   obbsat::ref     the scalar references, the specification of each method
#   obbsat::oracle  the exact contact oracle (separated / touching / overlapping)
# The hard-case suites (suites/, target obbsat_suites) are not part of the
# library: their headers live outside scalar_ref/include and kernel/include,
# so nothing here installs them.
#
# The version file follows 0.x rules while the major version is 0: a request
# for 0.1 accepts 0.1.z (z >= the requested patch) and nothing else, as every
# 0.minor release may change the interface. From 1.0 on, any later release of
# the same major version is accepted.

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Under add_subdirectory the parent project decides what it installs; it can
# still ask for obbsat's rules, e.g. to install a library of its own that
# links obbsat.
option(OBBSAT_INSTALL "Generate the install rules of obbsat" ${OBBSAT_TOP_LEVEL})

# The same target names whether obbsat is installed or added as a subdirectory.
if(NOT TARGET obbsat::ref)
  add_library(obbsat::ref ALIAS obbsat_ref)
endif()
set_target_properties(obbsat_ref PROPERTIES EXPORT_NAME ref)
set(obbsat_installed_libraries obbsat obbsat_ref)
if(TARGET obbsat_oracle)
  set_target_properties(obbsat_oracle PROPERTIES EXPORT_NAME oracle)
  list(APPEND obbsat_installed_libraries obbsat_oracle)
endif()

if(NOT OBBSAT_INSTALL)
  return()
endif()

set(obbsat_config_destination ${CMAKE_INSTALL_LIBDIR}/cmake/obbsat)

install(TARGETS ${obbsat_installed_libraries}
  EXPORT obbsat_targets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET obbsat_cli)
  install(TARGETS obbsat_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(obbsat_header_exclusions "")
if(NOT TARGET obbsat_oracle)
  list(APPEND obbsat_header_exclusions PATTERN "oracle" EXCLUDE)
endif()
install(DIRECTORY
    ${PROJECT_SOURCE_DIR}/scalar_ref/include/
    ${PROJECT_SOURCE_DIR}/kernel/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp"
  ${obbsat_header_exclusions})

install(EXPORT obbsat_targets
  NAMESPACE obbsat::
  FILE obbsatTargets.cmake
  DESTINATION ${obbsat_config_destination})

configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/obbsatConfig.cmake.in
  ${PROJECT_BINARY_DIR}/obbsatConfig.cmake
  INSTALL_DESTINATION ${obbsat_config_destination})
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(obbsat_version_compatibility SameMinorVersion)
else()
  set(obbsat_version_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/obbsatConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY ${obbsat_version_compatibility})
install(FILES
    ${PROJECT_BINARY_DIR}/obbsatConfig.cmake
    ${PROJECT_BINARY_DIR}/obbsatConfigVersion.cmake
  DESTINATION ${obbsat_config_destination})

# obbsat.pc names its prefix literally (pkg-config has no portable way to find
# it), and the prefix is only known once `cmake --install --prefix P` runs, so
# the file is written at install time rather than at configure time.
install(CODE "
set(obbsat_pc_template [==[${CMAKE_CURRENT_LIST_DIR}/obbsat.pc.in]==])
set(obbsat_pc_staging [==[${PROJECT_BINARY_DIR}/pkgconfig/obbsat.pc]==])
set(obbsat_pc_version [==[${PROJECT_VERSION}]==])
set(obbsat_pc_libdir_setting [==[${CMAKE_INSTALL_LIBDIR}]==])
set(obbsat_pc_includedir_setting [==[${CMAKE_INSTALL_INCLUDEDIR}]==])
")
install(CODE [==[
set(obbsat_pc_prefix "${CMAKE_INSTALL_PREFIX}")
foreach(kind libdir includedir)
  if(IS_ABSOLUTE "${obbsat_pc_${kind}_setting}")
    set(obbsat_pc_${kind} "${obbsat_pc_${kind}_setting}")
    set(obbsat_pc_${kind}_full "${obbsat_pc_${kind}_setting}")
  else()
    set(obbsat_pc_${kind} "\${prefix}/${obbsat_pc_${kind}_setting}")
    set(obbsat_pc_${kind}_full "${CMAKE_INSTALL_PREFIX}/${obbsat_pc_${kind}_setting}")
  endif()
endforeach()
configure_file("${obbsat_pc_template}" "${obbsat_pc_staging}" @ONLY)
file(INSTALL DESTINATION "${obbsat_pc_libdir_full}/pkgconfig" TYPE FILE FILES "${obbsat_pc_staging}")
]==])
