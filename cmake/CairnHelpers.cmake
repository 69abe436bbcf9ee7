# Helpers that give every Cairn target the same shape.
#
# Headers are included as <cairn/<module>/...> both in the build tree and after installation. In the build tree
# this works through ${CAIRN_BUILD_INCLUDE_DIR}/cairn/<module>, a symbolic link to the module's source folder.
set(CAIRN_BUILD_INCLUDE_DIR "${PROJECT_BINARY_DIR}/include")
file(MAKE_DIRECTORY "${CAIRN_BUILD_INCLUDE_DIR}/cairn")

set(CAIRN_WARNING_FLAGS -Wall -Wextra -Wpedantic)
if(CAIRN_WARNINGS_AS_ERRORS)
  list(APPEND CAIRN_WARNING_FLAGS -Werror)
endif()

# Exposes a top-level source folder (systems, optimization, ...) under <cairn/...> in the build tree and
# installs its headers under include/cairn/. Headers in any `internal/` folder are the libraries' own and are not
# installed, so no installed header may include one (the install test compiles every installed header).
function(cairn_expose_module module)
  set(link "${CAIRN_BUILD_INCLUDE_DIR}/cairn/${module}")
  if(NOT EXISTS "${link}")
    file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${module}" "${link}" SYMBOLIC)
  endif()
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${module}/" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cairn/${module}
    FILES_MATCHING PATTERN "*.h" PATTERN "internal" EXCLUDE)
endfunction()

# cairn_add_library(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Creates target cairn_<name>, alias Cairn::<name>, exported and installed as Cairn::<name>.
# PUBLIC_DEPS are what the library's installed headers include (they reach every user, and the package config
# must find them); everything only its sources use is PRIVATE.
function(cairn_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(cairn_${name} ${ARG_SOURCES})
  # The package config lists the components, and the install test checks that it uses every one of them.
  set_property(GLOBAL APPEND PROPERTY CAIRN_COMPONENTS ${name})
  add_library(Cairn::${name} ALIAS cairn_${name})
  set_target_properties(cairn_${name} PROPERTIES EXPORT_NAME ${name} VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  target_include_directories(cairn_${name} PUBLIC
    $<BUILD_INTERFACE:${CAIRN_BUILD_INCLUDE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(cairn_${name} PRIVATE ${CAIRN_WARNING_FLAGS})
  target_link_libraries(cairn_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  if(CAIRN_SANITIZE)
    # A sanitized library needs the sanitizer runtime first in every program that loads it, including outside
    # projects linking the installed package.
    target_link_options(cairn_${name} INTERFACE -fsanitize=address,undefined)
    # Eigen allocates differently under AddressSanitizer, so code inlined from Cairn's headers into an outside
    # project must be compiled the same way. (In-tree targets already use the global flags.)
    target_compile_options(cairn_${name} INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
  endif()
  install(TARGETS cairn_${name} EXPORT CairnTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()

# cairn_add_test(<name> SOURCES ... [LIBS ...])
# One GoogleTest executable per test folder; every TEST becomes its own ctest entry. Tests find the repository
# and the shared data through the compile definitions CAIRN_SOURCE_DIR and CAIRN_SHARED_DIR.
function(cairn_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${CAIRN_WARNING_FLAGS})
  target_compile_definitions(${name} PRIVATE
    CAIRN_SOURCE_DIR="${PROJECT_SOURCE_DIR}" CAIRN_SHARED_DIR="${CAIRN_SHARED_DIR}"
    CAIRN_BINARY_DIR="${PROJECT_BINARY_DIR}")
  # test/support holds helpers every suite may use (expect_throws.h, run_cairn.h).
  target_include_directories(${name} PRIVATE "${PROJECT_SOURCE_DIR}/test/support")
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gmock GTest::gtest_main)
  set(properties TIMEOUT 600)
  if(CAIRN_SANITIZE)
    list(APPEND properties ENVIRONMENT "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/test/support/lsan.supp")
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 120 PROPERTIES ${properties})
endfunction()

# cairn_add_benchmark(<name> SOURCES ... [LIBS ...])
function(cairn_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${CAIRN_WARNING_FLAGS})
  target_compile_definitions(${name} PRIVATE
    CAIRN_SOURCE_DIR="${PROJECT_SOURCE_DIR}" CAIRN_SHARED_DIR="${CAIRN_SHARED_DIR}")
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} benchmark::benchmark)
endfunction()
