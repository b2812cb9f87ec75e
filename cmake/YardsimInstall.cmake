# cmake --install produces a config package: find_package(yardsim CONFIG) from another project.
include(CMakePackageConfigHelpers)
install(EXPORT yardsimTargets NAMESPACE yardsim:: DESTINATION lib/cmake/yardsim)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/yardsimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/yardsimConfig.cmake INSTALL_DESTINATION lib/cmake/yardsim)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/yardsimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/yardsimConfig.cmake
  ${PROJECT_BINARY_DIR}/yardsimConfigVersion.cmake DESTINATION lib/cmake/yardsim)
