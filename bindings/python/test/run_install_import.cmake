# cmake -P script: install the build tree into a scratch prefix and import `cairn` from there (test python_install_import).
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${CAIRN_BUILD_DIR}" --prefix "${prefix}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${result}):\n${output}")
endif()
set(site "${prefix}/${PYTHON_INSTALL_DIR}")
if(NOT EXISTS "${site}/cairn/__init__.py")
  message(FATAL_ERROR "The package was not installed into ${site}/cairn")
endif()
# Nothing from the build tree: no PYTHONPATH but the prefix's, no LD_LIBRARY_PATH, run outside the source tree.
set(ENV{PYTHONPATH} "${site}")
set(ENV{LD_LIBRARY_PATH} "")
set(ENV{PYTHONDONTWRITEBYTECODE} "1")
execute_process(COMMAND "${PYTHON}" "${CHECK_SCRIPT}" "${prefix}" WORKING_DIRECTORY "${WORK_DIR}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "Importing the installed cairn failed (${result}).")
endif()
