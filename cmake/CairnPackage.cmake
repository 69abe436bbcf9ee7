# Package config so that an outside project can find_package(Cairn) and link any component (Cairn::systems,
# Cairn::perception, ...).
include(CMakePackageConfigHelpers)
set(CAIRN_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Cairn)

if(NOT BUILD_SHARED_LIBS)
  # A static library's private dependencies become part of what its users link, and several of Cairn's (Ipopt and
  # Bullet through pkg-config, CHOLMOD's include folder) are not packages that a config file can find again.
  message(STATUS "Cairn: static libraries are built for in-tree use only; `cmake --install` installs no package "
    "config (configure with -DBUILD_SHARED_LIBS=ON for an installable Cairn)")
  return()
endif()

get_property(CAIRN_COMPONENTS GLOBAL PROPERTY CAIRN_COMPONENTS)

# The installed targets' interfaces name other Cairn components and third-party targets; CairnConfig.cmake must find
# the package of every third-party target that appears there, and no other. Which packages those are follows from
# the PUBLIC dependencies (what installed headers include), so they are read here from the targets rather than kept
# by hand: a PUBLIC dependency that CairnConfig.cmake.in does not know stops the configuration, and each package is
# looked for only when a component that needs it is asked for.
#
# Third-party targets allowed in installed interfaces, and the variable listing the components that need each.
set(_cairn_public_targets Eigen3::Eigen opencv_core)
set(_cairn_public_target_lists CAIRN_EIGEN_COMPONENTS CAIRN_OPENCV_COMPONENTS)

# The third-party targets in the interface of cairn_<component>, following the Cairn components it names.
function(_cairn_public_closure component out)
  set(result "")
  set(pending "cairn_${component}")
  set(seen "")
  while(pending)
    list(POP_FRONT pending target)
    if(target IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${target})
    get_target_property(deps ${target} INTERFACE_LINK_LIBRARIES)
    if(NOT deps)
      continue()
    endif()
    foreach(dep IN LISTS deps)
      if(dep MATCHES "^::@")
        # CMake's marker around entries added by target_link_libraries() from another folder (perception/friction).
        continue()
      endif()
      if(dep MATCHES "^Cairn::(.+)$")
        list(APPEND pending "cairn_${CMAKE_MATCH_1}")
      elseif(dep MATCHES "^cairn_")
        list(APPEND pending ${dep})
      else()
        list(APPEND result ${dep})
      endif()
    endforeach()
  endwhile()
  list(REMOVE_DUPLICATES result)
  set(${out} ${result} PARENT_SCOPE)
endfunction()

foreach(list_name IN LISTS _cairn_public_target_lists)
  set(${list_name} "")
endforeach()
foreach(component IN LISTS CAIRN_COMPONENTS)
  _cairn_public_closure(${component} deps)
  foreach(dep IN LISTS deps)
    list(FIND _cairn_public_targets "${dep}" index)
    if(index EQUAL -1)
      message(FATAL_ERROR "Cairn::${component} has the public dependency '${dep}', which the installed package "
        "config does not find: make it PRIVATE if no installed header of Cairn::${component} includes its headers, "
        "or add its find_dependency() to cmake/CairnConfig.cmake.in and its target to cmake/CairnPackage.cmake.")
    endif()
    list(GET _cairn_public_target_lists ${index} list_name)
    list(APPEND ${list_name} ${component})
  endforeach()
endforeach()

install(EXPORT CairnTargets NAMESPACE Cairn:: DESTINATION ${CAIRN_CMAKE_INSTALL_DIR})
configure_package_config_file(cmake/CairnConfig.cmake.in "${PROJECT_BINARY_DIR}/CairnConfig.cmake"
  INSTALL_DESTINATION ${CAIRN_CMAKE_INSTALL_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/CairnConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/CairnConfig.cmake" "${PROJECT_BINARY_DIR}/CairnConfigVersion.cmake"
  DESTINATION ${CAIRN_CMAKE_INSTALL_DIR})
