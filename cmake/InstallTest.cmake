# Installs the build into a scratch prefix and imports gdpn from there with a clean PYTHONPATH.
set(prefix "${BINARY_DIR}/install-test")
file(REMOVE_RECURSE "${prefix}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BINARY_DIR}" --prefix "${prefix}" --component Unspecified
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${prefix}/${SUBDIR}" "${PYTHON}" -P -c
                        "import gdpn, os; assert gdpn.__file__.startswith(os.environ['PYTHONPATH']), gdpn.__file__; print('installed gdpn', gdpn.__version__)"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import gdpn from the install folder failed")
endif()
