# Runs CMD (a ;-list) and checks its exit code and output.
#   cmake -DCMD="prog|arg|arg" -DEXPECT_CODE=2 [-DEXPECT_STDOUT=regex] [-DEXPECT_STDERR=regex]
#         [-DREFUSE_STDERR=regex] -P expect.cmake
# REFUSE_STDERR: what stderr must not hold (a digest, a file's contents).
string(REPLACE "|" ";" CMD "${CMD}")
execute_process(COMMAND ${CMD} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code STREQUAL EXPECT_CODE)
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}':\n${out}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}':\n${err}")
endif()
if(DEFINED REFUSE_STDERR AND err MATCHES "${REFUSE_STDERR}")
  message(FATAL_ERROR "stderr matches '${REFUSE_STDERR}', which it must not:\n${err}")
endif()
if(err MATCHES "terminate called|Segmentation|Aborted")
  message(FATAL_ERROR "crashed:\n${err}")
endif()
