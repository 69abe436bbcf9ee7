# Package config so that an outside project can find_package(Cairn) and link Cairn::systems, ...
include(CMakePackageConfigHelpers)
set(CAIRN_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Cairn)
install(EXPORT CairnTargets NAMESPACE Cairn:: DESTINATION ${CAIRN_CMAKE_INSTALL_DIR})
configure_package_config_file(cmake/CairnConfig.cmake.in "${PROJECT_BINARY_DIR}/CairnConfig.cmake"
  INSTALL_DESTINATION ${CAIRN_CMAKE_INSTALL_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/CairnConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/CairnConfig.cmake" "${PROJECT_BINARY_DIR}/CairnConfigVersion.cmake"
  DESTINATION ${CAIRN_CMAKE_INSTALL_DIR})
