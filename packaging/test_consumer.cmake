# ctest: install the build into a scratch prefix, build packaging/consumer against it with
# find_package(bemcontact), run it on the installed examples/plate_tension.toml. The plate
# (E = 1e5, P = 1, height 2) stretches by exactly 2 P / E = 2e-5 at the top (linear elements
# reproduce the linear field to round-off), and the consumer reports the build's version.
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
execute_process(COMMAND ${WORK_DIR}/build/consumer ${WORK_DIR}/prefix/share/bemcontact/examples/plate_tension.toml
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(status)
  message(FATAL_ERROR "the consumer failed:\n${out}")
endif()
if(NOT out MATCHES "bemcontact ${VERSION}\n")
  message(FATAL_ERROR "the consumer reports another version:\n${out}")
endif()
string(REGEX MATCH "u2_max ([0-9.e+-]+)" match "${out}")
if(NOT match OR CMAKE_MATCH_1 LESS 1.99999e-05 OR CMAKE_MATCH_1 GREATER 2.00001e-05)
  message(FATAL_ERROR "the consumer's answer is not 2 P / E = 2e-5:\n${out}")
endif()
message(STATUS "consumer: ${out}")
