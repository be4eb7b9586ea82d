# Install the module interface units and an exported target, so that a consumer does
# find_package(incidence CONFIG REQUIRED) and import incidence; (the BMI is rebuilt there).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
install(TARGETS incidence EXPORT incidence-targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    FILE_SET CXX_MODULES DESTINATION ${CMAKE_INSTALL_DATADIR}/incidence/modules)
install(EXPORT incidence-targets NAMESPACE incidence::
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/incidence
    CXX_MODULES_DIRECTORY cxx-modules)
configure_package_config_file(cmake/incidence-config.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/incidence-config.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/incidence)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/incidence-config-version.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/incidence-config.cmake
    ${CMAKE_CURRENT_BINARY_DIR}/incidence-config-version.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/incidence)
