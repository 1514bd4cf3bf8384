# Runs ossa-sim --count with 1 thread and with THREADS threads and requires the same poses
# (pose_hash of the first creature, herd_pose_hash of the others): step_all is bit-identical
# on any number of threads (issue 31).
#   cmake -DSIM=path/to/ossa-sim -DARGS="--example|horse|--count|64|--script|walk:0.6:3" -DTHREADS=2 -P sim_threads_check.cmake
string(REPLACE "|" ";" args "${ARGS}")
foreach(t 1 ${THREADS})
  execute_process(COMMAND ${SIM} ${args} --threads ${t} --json RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ossa-sim --threads ${t} failed (${rc}): ${err}")
  endif()
  string(JSON herd_${t} GET "${json}" herd_pose_hash)
  string(JSON pose_${t} GET "${json}" pose_hash)
  string(JSON used_${t} GET "${json}" threads)
endforeach()
if(NOT used_${THREADS} EQUAL THREADS)
  message(FATAL_ERROR "ossa-sim --threads ${THREADS} reported ${used_${THREADS}} threads")
endif()
if(NOT herd_1 STREQUAL herd_${THREADS} OR NOT pose_1 STREQUAL pose_${THREADS})
  message(FATAL_ERROR "poses differ: 1 thread ${pose_1} ${herd_1}, ${THREADS} threads ${pose_${THREADS}} ${herd_${THREADS}}")
endif()
message(STATUS "1 and ${THREADS} threads: pose_hash ${pose_1}, herd_pose_hash ${herd_1}")
