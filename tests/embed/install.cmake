# The fixture of the install: and embed: tests: installs the already built ossa into PREFIX
# (a fresh folder), as an embedder would with `cmake --install build/release --prefix P`.
#   OSSA_BUILD_DIR  the build tree;  PREFIX  the scratch prefix
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${OSSA_BUILD_DIR} --prefix ${PREFIX}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})\n${out}\n${err}")
endif()
