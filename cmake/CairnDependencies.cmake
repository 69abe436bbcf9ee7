# Every third-party package Cairn uses, found once. scripts/install_deps.sh installs them all from Debian.
# Notes on each (why these exact calls) are in shared/notes/dependencies.md.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
find_package(NLopt 2.7 CONFIG REQUIRED HINTS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/nlopt_cxx)
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
if(NOT TARGET Cairn::Cholmod)
  add_library(cairn_cholmod INTERFACE)
  target_include_directories(cairn_cholmod INTERFACE ${CHOLMOD_INCLUDE_DIR})
  target_link_libraries(cairn_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})
  add_library(Cairn::Cholmod ALIAS cairn_cholmod)
endif()
find_package(fcl 0.7 CONFIG REQUIRED)
find_package(urdfdom CONFIG REQUIRED)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs calib3d ml dnn ximgproc)
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
find_package(yaml-cpp CONFIG REQUIRED)
find_package(nlohmann_json 3.11 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)

if(CAIRN_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
  include(GoogleTest)
endif()
if(CAIRN_BENCHMARKS)
  find_package(benchmark CONFIG REQUIRED)
endif()
if(CAIRN_BUILD_TESTS OR CAIRN_BENCHMARKS)
  # Peers for cross-checks and benchmarks only; never linked into Cairn's libraries.
  find_package(DART 6.12 CONFIG REQUIRED COMPONENTS utils-urdf)
  find_package(octomap CONFIG QUIET)
  # PCL (Debian's libpcl-dev) through pkg-config: PCLConfig.cmake would look for VTK, Qt and more than the
  # haptics cross-check (voxel grid, RANSAC sphere, octree change detection) needs.
  pkg_check_modules(PCL_PEER QUIET IMPORTED_TARGET pcl_filters pcl_octree pcl_sample_consensus pcl_common)
endif()

# Python bindings (bindings/python): Debian's /usr/bin/python3 with numpy (the python3 on PATH may be another
# interpreter without it) and pybind11. Not searched for sanitized builds: an AddressSanitizer-instrumented extension
# loads only into a python3 started with the sanitizer runtime in LD_PRELOAD. CAIRN_WITH_PYTHON (top-level
# CMakeLists.txt) defaults to whether both were found.
set(CAIRN_PYTHON_FOUND OFF)
if(NOT CAIRN_SANITIZE AND (NOT DEFINED CAIRN_WITH_PYTHON OR CAIRN_WITH_PYTHON))
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  set(PYBIND11_FINDPYTHON ON)
  # Development.Embed (libpython) only for benchmarks/binding_benchmark.cc, which embeds the interpreter.
  find_package(Python 3.11 COMPONENTS Interpreter Development.Module NumPy OPTIONAL_COMPONENTS Development.Embed)
  if(Python_FOUND)
    find_package(pybind11 2.10 CONFIG)
  endif()
  if(Python_FOUND AND pybind11_FOUND)
    set(CAIRN_PYTHON_FOUND ON)
  endif()
endif()
