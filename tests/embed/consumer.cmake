# Shared by the install tests' scripts (tests/embed/CMakeLists.txt is the consumer project of
# run_embed_test.cmake): run a command or fail with its output, and configure + build a
# consumer project against the scratch install.
#   PREFIX        the scratch install (made by install.cmake, the fixture of these tests)
#   CXX_COMPILER  ossa's compiler: a sanitizer runtime is the compiler's own
#   GENERATOR     ossa's CMake generator;  CCACHE  a compiler launcher, or empty
#   OSSA_SANITIZE, OSSA_FUZZ  the consumer gets the same sanitizers as ossa

# run(<command...>): fails the test with the command's output when it fails; its stdout lands
# in `run_out` of the caller.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
  set(run_out "${out}" PARENT_SCOPE)
endfunction()

# build_consumer(SOURCE_DIR BUILD_DIR): configure with find_package(ossa) from PREFIX, build.
function(build_consumer source_dir build_dir)
  set(extra "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
  if(OSSA_SANITIZE OR OSSA_FUZZ)
    list(APPEND extra "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
      "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
  endif()
  if(CCACHE)
    list(APPEND extra "-DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE}")
  endif()
  file(REMOVE_RECURSE ${build_dir})
  run(${CMAKE_COMMAND} -S ${source_dir} -B ${build_dir} -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${PREFIX}
    -DCMAKE_BUILD_TYPE=Release ${extra})
  run(${CMAKE_COMMAND} --build ${build_dir})
endfunction()
