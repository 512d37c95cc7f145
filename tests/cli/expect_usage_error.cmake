# Runs COMMAND (its arguments separated by '|') and passes only if it exits with status 2 (bad usage) AND its
# stderr matches EXPECTED: the message alone, or the exit code alone, is not enough.
#   cmake -DCOMMAND="raycam-cli|render|--res|0" -DEXPECTED="--res: expected" -P expect_usage_error.cmake
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2)
  message(FATAL_ERROR "exit status ${status}, expected 2 (bad usage)\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "${EXPECTED}")
  message(FATAL_ERROR "stderr does not match '${EXPECTED}':\n${err}")
endif()
