# feel's version, from project(feel VERSION ...): the one place it is written.
#
# Generates feel/version.h (FEEL_VERSION_MAJOR/MINOR/PATCH, FEEL_VERSION,
# FEEL_VERSION_STRING) into the build tree, and defines FEEL_PUBLIC_INCLUDE_DIRS, the
# include directories every public library carries: the source tree's include/ and the
# generated header's directory while building, <prefix>/include once installed.
include(GNUInstallDirs)

set(FEEL_GENERATED_INCLUDE_DIR ${PROJECT_BINARY_DIR}/generated/include)
configure_file(${PROJECT_SOURCE_DIR}/include/feel/version.h.in
               ${FEEL_GENERATED_INCLUDE_DIR}/feel/version.h @ONLY)

set(FEEL_PUBLIC_INCLUDE_DIRS
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${FEEL_GENERATED_INCLUDE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)

# The shared C library's ABI version: its SONAME is libfeel.so.${FEEL_SOVERSION}. It
# changes only when a change breaks binaries built against an older libfeel (docs/c-api.md,
# "ABI evolution"); while feel is 0.x that is 0.
set(FEEL_SOVERSION 0)
