# `cmake --install` puts the libraries, headers and a package config in place so that another
# project can `find_package(mobb)` and link mobb::core (and mobb::io).
include(CMakePackageConfigHelpers)
install(TARGETS mobb_core mobb_io EXPORT mobbTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/mobb DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN "crowd" EXCLUDE PATTERN "util" EXCLUDE)
install(EXPORT mobbTargets NAMESPACE mobb:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mobb)
configure_package_config_file(cmake/mobbConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/mobbConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mobb)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/mobbConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/mobbConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/mobbConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mobb)
