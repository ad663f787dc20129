# ctest -P check, run as the test `CtestNames.AreReadable`: every test name is at most 120
# characters and holds no printout of a test parameter (`GetParam() = 128-byte object <B0-19 …>`,
# a byte dump with pointers in it, so names would change between builds).
#   cmake -DCTEST=<ctest> -DBUILD_DIR=<build folder> -P tests/ctest_names.cmake
execute_process(COMMAND ${CTEST} -N WORKING_DIRECTORY ${BUILD_DIR}
  OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ctest -N failed (${status})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(count 0)
foreach(line IN LISTS lines)
  if(line MATCHES "Test +#[0-9]+: (.*)$")
    set(name "${CMAKE_MATCH_1}")
    math(EXPR count "${count} + 1")
    string(LENGTH "${name}" length)
    if(length GREATER 120)
      message(SEND_ERROR "test name of ${length} characters: ${name}")
    endif()
    if(name MATCHES "GetParam|byte object|#")
      message(SEND_ERROR "test name with a parameter printout: ${name}")
    endif()
  endif()
endforeach()
if(count LESS 10)
  message(FATAL_ERROR "found only ${count} tests in the listing:\n${listing}")
endif()
message(STATUS "${count} test names, all readable")
