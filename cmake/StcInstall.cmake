# Install rules and the exported package: find_package(stcontact) + stcontact::stcontact.
include(CMakePackageConfigHelpers)
get_property(stc_targets GLOBAL PROPERTY STC_EXPORTED_TARGETS)
install(TARGETS ${stc_targets} stcontact EXPORT stcontactTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS stcontact_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(stc_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/stcontact)
install(EXPORT stcontactTargets NAMESPACE stcontact:: DESTINATION ${stc_cmake_dir})
configure_package_config_file(cmake/stcontactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/stcontactConfig.cmake INSTALL_DESTINATION ${stc_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/stcontactConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/stcontactConfig.cmake
              ${PROJECT_BINARY_DIR}/stcontactConfigVersion.cmake
              cmake/FindCHOLMOD.cmake cmake/FindARPACK.cmake cmake/FindOpenBLAS.cmake
        DESTINATION ${stc_cmake_dir})
# The licence and the citation metadata, beside the documentation of the installed package.
install(FILES LICENSE CITATION.cff DESTINATION ${CMAKE_INSTALL_DOCDIR})
