# `cmake --install build --prefix P` gives headers, the library and a CMake package,
# so an outside project can `find_package(tide)` and link `tide::core`.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS tide_core tide_io EXPORT tideTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The renderer and viewer are build-tree libraries (apps and examples), not installed.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/tide DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  PATTERN render EXCLUDE PATTERN view EXCLUDE)
install(EXPORT tideTargets NAMESPACE tide:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tide)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tideConfig.cmake.in
  ${PROJECT_BINARY_DIR}/tideConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tide)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tideConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tideConfig.cmake ${PROJECT_BINARY_DIR}/tideConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/TideOpenVDB.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tide)
