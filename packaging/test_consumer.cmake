# ctest: install the build into a scratch prefix, build packaging/consumer against it with
# find_package(bemcontact), run it. Its uniaxial square (E = 1000, t = 10, height 1) must
# stretch by t/E = 0.01 at the top, and report the build's version.
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR VERSION)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "test_consumer.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "cmake --install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/packaging/consumer -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(status)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
if(status)
  message(FATAL_ERROR "building the consumer failed:\n${out}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE status OUTPUT_VARIABLE out)
if(status)
  message(FATAL_ERROR "the consumer failed:\n${out}")
endif()
if(NOT out MATCHES "bemcontact ${VERSION}\n")
  message(FATAL_ERROR "the consumer reports another version:\n${out}")
endif()
string(REGEX MATCH "u2_top ([0-9.e+-]+)" match "${out}")
if(NOT match OR CMAKE_MATCH_1 LESS 0.00999 OR CMAKE_MATCH_1 GREATER 0.01001)
  message(FATAL_ERROR "the consumer's answer is not t/E = 0.01:\n${out}")
endif()
message(STATUS "consumer: ${out}")
