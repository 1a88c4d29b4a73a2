# Installs the python component of the build tree BUILD_DIR into PREFIX,
# emptied first, as a user would with `cmake --install BUILD_DIR --prefix PREFIX`.
file(REMOVE_RECURSE ${PREFIX})
execute_process(
  COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --component python --prefix ${PREFIX}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} --component python failed")
endif()
