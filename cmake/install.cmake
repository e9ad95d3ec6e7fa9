# `cmake --install` puts the command, the core library, its public headers
# and a CMake package in the prefix, so that a separate project can build a
# plugin with find_package(hystbench) and the same registration macro. The
# build tree holds the same package (headers from the source tree), so a
# plugin also builds against it without installing: -Dhystbench_DIR=<build>.
include(CMakePackageConfigHelpers)

install(TARGETS hystbench_core hystbench
        EXPORT hystbenchTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY framework problems
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hystbench
        FILES_MATCHING PATTERN "*.hpp"
        PATTERN "cluster" EXCLUDE)  # part of the command, not of the library
install(EXPORT hystbenchTargets
        NAMESPACE hystbench::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hystbench)
export(EXPORT hystbenchTargets
       NAMESPACE hystbench::
       FILE ${CMAKE_BINARY_DIR}/hystbenchTargets.cmake)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/hystbenchConfig.cmake.in
  ${CMAKE_BINARY_DIR}/hystbenchConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hystbench)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/hystbenchConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/hystbenchConfig.cmake
              ${CMAKE_BINARY_DIR}/hystbenchConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hystbench)
