# Install rules (MESHPREP_INSTALL): every registered module's static library and headers, the
# umbrella target, the exported targets (namespace meshprep::), meshprepConfig.cmake with its
# version file and the find modules (TetGen, GMP), so that another project can
#   find_package(meshprep REQUIRED)
#   target_link_libraries(app PRIVATE meshprep::meshprep)
# Included after meshprep_add_umbrella_target(), once every module has registered itself.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MESHPREP_CONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/meshprep)
get_property(meshprep_modules GLOBAL PROPERTY MESHPREP_MODULES)

# 1. The libraries and the umbrella, in the export set.
install(TARGETS ${meshprep_modules} meshprep_umbrella EXPORT meshprepTargets)

# 2. Each module's public headers (<module>/include/meshprep/<module>/*.h).
foreach(module IN LISTS meshprep_modules)
  get_target_property(module_dir ${module} SOURCE_DIR)
  install(DIRECTORY ${module_dir}/include/ TYPE INCLUDE FILES_MATCHING PATTERN "*.h")
endforeach()

# 3. The exported targets, the package config and its version, and the find modules the config
#    needs (the static libraries carry TetGen::tetgen, GMP::gmp and GMP::gmpxx as link-only dependencies).
install(EXPORT meshprepTargets NAMESPACE meshprep:: DESTINATION ${MESHPREP_CONFIG_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/meshprepConfig.cmake.in
  ${PROJECT_BINARY_DIR}/meshprepConfig.cmake INSTALL_DESTINATION ${MESHPREP_CONFIG_DIR})
# 0.x: a minor release may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/meshprepConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/meshprepConfig.cmake ${PROJECT_BINARY_DIR}/meshprepConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindTetGen.cmake ${PROJECT_SOURCE_DIR}/cmake/FindGMP.cmake
              ${PROJECT_SOURCE_DIR}/cmake/meshprep_find_imported.cmake
        DESTINATION ${MESHPREP_CONFIG_DIR})
