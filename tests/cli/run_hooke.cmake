# Helpers of the CLI tests: run hooke and require success (its stdout in `out`), or exit code 2 with a message
# matching a pattern and without the named file written.
function(run_ok name)
  execute_process(COMMAND ${HOOKE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "hooke ${name} failed with ${rc}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

function(run_fails name pattern file)
  execute_process(COMMAND ${HOOKE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${pattern}" OR (NOT file STREQUAL "" AND EXISTS ${file}))
    message(FATAL_ERROR "${name} must fail with exit code 2 naming '${pattern}' (got ${rc}: ${err})")
  endif()
  message("refused as it should: ${err}")
endfunction()
