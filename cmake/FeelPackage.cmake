# feel as a package: the targets a consumer links, install rules, feelConfig.cmake and
# feel.pc.
#
#   feel::feel    the C++ host API (feel/host/*.hpp, the §8 wrappers feel/iforce.hpp) and
#                 everything it needs: a game's C++ entry point
#   feel::engine  the effect engine alone (feel/engine.hpp), for firmware-like use
#   feel::c       the C ABI (feel/feel.h), the shared library libfeel.so
#
# The same names work in a parent project that adds feel with add_subdirectory() or
# FetchContent (ALIAS targets) and after find_package(feel) (imported targets). The C++
# libraries are static: their internal libraries (feel_protocol, feel_transport, ...) are
# installed and exported too, because a static library's dependencies must be linked by
# whoever links it; their PRIVATE header-only dependencies (nlohmann-json, Boost.Asio) are
# not (no public header includes them). A library added to the export list below must have
# every library it links PUBLIC in the list too.

# feel::feel: the host API with the wrappers.
add_library(feel_cxx INTERFACE)
target_link_libraries(feel_cxx INTERFACE feel_host feel_iforce)
target_compile_features(feel_cxx INTERFACE cxx_std_20)
set_target_properties(feel_cxx PROPERTIES EXPORT_NAME feel)

add_library(feel::feel ALIAS feel_cxx)
add_library(feel::engine ALIAS feel_engine)
add_library(feel::c ALIAS feel_capi)

if(NOT FEEL_INSTALL)
  return()
endif()

include(CMakePackageConfigHelpers)

# Exported name of each installed library: feel::<name>.
set(FEEL_EXPORTED_LIBRARIES
    feel_engine:engine feel_sim:sim feel_runtime:runtime feel_protocol:protocol
    feel_transport:transport feel_peripheral:peripheral feel_format:format
    feel_host:host feel_iforce:iforce feel_capi:c feel_cxx:feel
    # the static libraries link it PRIVATE (compile warnings only); exported because a
    # static library's private links are recorded, it carries no usage requirement.
    feel_warnings:warnings)
set(FEEL_INSTALL_TARGETS)
foreach(entry ${FEEL_EXPORTED_LIBRARIES})
  string(REPLACE ":" ";" pair ${entry})
  list(GET pair 0 target)
  list(GET pair 1 name)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  list(APPEND FEEL_INSTALL_TARGETS ${target})
endforeach()

install(TARGETS ${FEEL_INSTALL_TARGETS} EXPORT feelTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
                NAMELINK_COMPONENT development
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/feel DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(FILES ${FEEL_GENERATED_INCLUDE_DIR}/feel/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/feel COMPONENT development)

set(FEEL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/feel)
install(EXPORT feelTargets NAMESPACE feel:: DESTINATION ${FEEL_CMAKE_DIR} COMPONENT development)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/feelConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/feelConfig.cmake
                              INSTALL_DESTINATION ${FEEL_CMAKE_DIR})
# 0.x releases are compatible only within the same minor version; from 1.0 on, within the
# same major version.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(FEEL_COMPATIBILITY SameMinorVersion)
else()
  set(FEEL_COMPATIBILITY SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/feelConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY ${FEEL_COMPATIBILITY})
install(FILES ${PROJECT_BINARY_DIR}/feelConfig.cmake ${PROJECT_BINARY_DIR}/feelConfigVersion.cmake
        DESTINATION ${FEEL_CMAKE_DIR} COMPONENT development)

# pkg-config, for C programs: the C ABI (libfeel.so) only. Relocatable: the prefix is
# found from the .pc file's own place, so `cmake --install --prefix` anywhere works.
file(RELATIVE_PATH FEEL_PC_TO_PREFIX /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
configure_file(${PROJECT_SOURCE_DIR}/cmake/feel.pc.in ${PROJECT_BINARY_DIR}/feel.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/feel.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT development)

# The command line, the documentation and the examples.
if(TARGET feel AND FEEL_BUILD_CLI)
  install(TARGETS feel RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT doc)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT doc)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        COMPONENT doc PATTERN "CMakeLists.txt" EXCLUDE)
