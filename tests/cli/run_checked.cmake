# Shared by the cmake -P checks that run a program in a folder of their own (included):
#   run_checked(PROGRAM NAME EXPECTED_CODE ARGS...) runs PROGRAM with ARGS in WORK, fails the test
#   (naming NAME) unless it exits EXPECTED_CODE and without crashing, and leaves its output in
#   `out` and `err`;
#   expect_match(TEXT REGEX WHAT) fails unless TEXT matches REGEX.
function(run_checked program name expected_code)
  execute_process(COMMAND "${program}" ${ARGN} WORKING_DIRECTORY "${WORK}" TIMEOUT 60
    RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  if(NOT code STREQUAL "${expected_code}")
    message(FATAL_ERROR "${name} ${ARGN}: exit ${code}, expected ${expected_code}\nstdout:\n${stdout}\nstderr:\n${stderr}")
  endif()
  if(stderr MATCHES "terminate called|Segmentation|Aborted")
    message(FATAL_ERROR "${name} ${ARGN} crashed:\n${stderr}")
  endif()
  set(out "${stdout}" PARENT_SCOPE)
  set(err "${stderr}" PARENT_SCOPE)
endfunction()

function(expect_match text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what} does not match '${regex}':\n${text}")
  endif()
endfunction()
