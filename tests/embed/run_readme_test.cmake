# Run by CTest: README.md's "Embedding" program, copied verbatim from README_FILE (the fenced
# block after each "<!-- embed: FILE ... -->" marker), built against the scratch install PREFIX
# (install.cmake; consumer.cmake for the other variables) and run from another folder: with the
# installed data it walks the horse; with a folder that has no level it fails with the
# missing file's name.
include(${CMAKE_CURRENT_LIST_DIR}/consumer.cmake)

file(READ ${README_FILE} readme)
file(REMOVE_RECURSE ${WORK_DIR})
foreach(name CMakeLists.txt main.cpp)
  string(FIND "${readme}" "<!-- embed: ${name} " at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${README_FILE}: no \"<!-- embed: ${name}\" marker")
  endif()
  string(SUBSTRING "${readme}" ${at} -1 rest)
  # The block: from the line after its opening fence to its closing fence.
  string(FIND "${rest}" "```" open)
  string(SUBSTRING "${rest}" ${open} -1 rest)
  string(FIND "${rest}" "\n" eol)
  math(EXPR begin "${eol} + 1")
  string(SUBSTRING "${rest}" ${begin} -1 rest)
  string(FIND "${rest}" "\n```" close)
  if(close EQUAL -1)
    message(FATAL_ERROR "${README_FILE}: the block after \"<!-- embed: ${name}\" is not closed")
  endif()
  math(EXPR close "${close} + 1")
  string(SUBSTRING "${rest}" 0 ${close} text)
  file(WRITE ${WORK_DIR}/src/${name} "${text}")
endforeach()

build_consumer(${WORK_DIR}/src ${WORK_DIR}/build)
file(MAKE_DIRECTORY ${WORK_DIR}/elsewhere)
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=OSSA_SOURCE_DIR ${WORK_DIR}/build/my_game
  WORKING_DIRECTORY ${WORK_DIR}/elsewhere
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "my_game: exit ${rc}\n${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "my_game: a horse of [0-9]+ bones walked from x = ")
  message(FATAL_ERROR "my_game did not walk the horse (exit ${rc})")
endif()
# The horse walked forwards: at half stick, well over a metre in two seconds.
string(REGEX MATCH "from x = (-?[0-9.]+) m to x = (-?[0-9.]+) m" _ "${out}")
if("${CMAKE_MATCH_2}" STREQUAL "" OR CMAKE_MATCH_2 LESS_EQUAL CMAKE_MATCH_1)
  message(FATAL_ERROR "my_game: the horse did not move forwards")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=OSSA_SOURCE_DIR ${WORK_DIR}/build/my_game ${WORK_DIR}/elsewhere
  WORKING_DIRECTORY ${WORK_DIR}/elsewhere
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "my_game ${WORK_DIR}/elsewhere: exit ${rc}\n${out}${err}")
if(NOT rc EQUAL 1 OR NOT err MATCHES "^my_game: ${WORK_DIR}/elsewhere/levels/default\\.json: ")
  message(FATAL_ERROR "my_game on a folder without levels/ should fail with the missing file's name")
endif()
