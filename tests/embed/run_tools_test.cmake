# Run by CTest: the installed game and tools of the scratch install PREFIX (install.cmake) run
# from another folder with OSSA_SOURCE_DIR unset, finding levels/, assets/ and shaders/ in
# PREFIX/share/ossa next to their bin/ (src/ossa/io/data_dir.h). A copy of ossa-gen in a
# second prefix whose share/ossa has no assets/ names that prefix's missing file: the data
# comes from beside the executable, not from the source tree.
#   PREFIX, WORK_DIR; HAVE_RENDER, HAVE_GAME (ossa-render, ossa installed); RENDER_ENV (the
#   tools' extra environment, VAR=VALUE entries separated by '|': a ';' would split the test's command)
string(REPLACE "|" ";" RENDER_ENV "${RENDER_ENV}")
file(REMOVE_RECURSE ${WORK_DIR})
set(elsewhere ${WORK_DIR}/elsewhere)
file(MAKE_DIRECTORY ${elsewhere})

# tool(EXPECT_RC REGEX COMMAND...): runs COMMAND; its stdout+stderr must match REGEX (if not empty).
function(tool expect_rc regex)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=OSSA_SOURCE_DIR ${RENDER_ENV} ${ARGN}
    WORKING_DIRECTORY ${elsewhere} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(SUBSTRING "${out}" 0 400 shown)
  message(STATUS "${ARGN}: exit ${rc}\n${shown}\n${err}")
  if(NOT rc STREQUAL "${expect_rc}" OR (NOT regex STREQUAL "" AND NOT "${out}${err}" MATCHES "${regex}"))
    message(FATAL_ERROR "expected exit ${expect_rc} and output matching \"${regex}\"")
  endif()
endfunction()

set(bin ${PREFIX}/bin)
set(levels ${PREFIX}/share/ossa/levels)
tool(0 "\"name\": \"horse\"" ${bin}/ossa-gen --example horse --summary)
tool(0 "\"gait\": \"walk\".*\"x_reached\": [0-9]" ${bin}/ossa-sim --example horse
  --level ${levels}/default.json --script walk:0.5:2 --json)
# With no --level, ossa-sim walks on the installed levels/default.json.
tool(0 "\"level\": \"${levels}/default[.]json\"" ${bin}/ossa-sim --example pig --script walk:0.5:1 --json)
if(HAVE_RENDER)
  # Shaders and bone sprites from share/ossa.
  tool(0 "\"draw_calls\": [1-9]" ${bin}/ossa-render --example horse --level ${levels}/stairs.json
    --png ${elsewhere}/horse.png --stats)
  if(NOT EXISTS ${elsewhere}/horse.png)
    message(FATAL_ERROR "ossa-render wrote no ${elsewhere}/horse.png")
  endif()
endif()

if(HAVE_GAME)
  # The game: level, creatures, prototypes, shaders, sprites and the gamepad database.
  tool(0 "" ${bin}/ossa --headless --frames 30 --png ${elsewhere}/game.png --state ${elsewhere}/state.json)
  file(READ ${elsewhere}/state.json state)
  if(NOT EXISTS ${elsewhere}/game.png OR NOT state MATCHES "\"format\": \"ossa.state\".*\"creature\": \"horse\"")
    message(FATAL_ERROR "the installed ossa wrote no picture or no state:\n${state}")
  endif()
endif()

# A prefix with levels/ but no assets/: the installed ossa-gen looks there, and says so.
set(moved ${WORK_DIR}/moved)
file(MAKE_DIRECTORY ${moved}/bin ${moved}/share/ossa)
file(COPY ${bin}/ossa-gen DESTINATION ${moved}/bin)
file(COPY ${levels} DESTINATION ${moved}/share/ossa)
tool(1 "${moved}/share/ossa/assets/creatures/examples\\.json" ${moved}/bin/ossa-gen --example horse --summary)
