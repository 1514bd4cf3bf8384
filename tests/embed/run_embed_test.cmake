# Run by CTest: installs the already built ossa into WORK_DIR/prefix, then configures, builds
# and runs the consumer project in EMBED_SOURCE_DIR against it.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

run(${CMAKE_COMMAND} --install ${OSSA_BUILD_DIR} --prefix ${prefix})
# The consumer is built by the same compiler as ossa (a sanitizer runtime is the compiler's
# own), with the same sanitizers.
set(extra "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
if(OSSA_SANITIZE OR OSSA_FUZZ)
  list(APPEND extra "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
run(${CMAKE_COMMAND} -S ${EMBED_SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release ${extra})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/embed_demo ${prefix}/share/ossa/levels/default.json ${prefix}/share/ossa/assets/creatures/examples.json)
# load_level reads Tiled and LDtk files for embedders too (pugixml and zlib come through
# the package config).
run(${WORK_DIR}/build/embed_demo ${EMBED_SOURCE_DIR}/../level/data/tiles_zlib.tmx ${prefix}/share/ossa/assets/creatures/examples.json)
run(${WORK_DIR}/build/embed_demo "${EMBED_SOURCE_DIR}/../level/data/world.ldtk#Level_1" ${prefix}/share/ossa/assets/creatures/examples.json)
