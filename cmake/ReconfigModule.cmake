# reconfig_add_module(NAME DEPENDS <targets...>)
#   A library `reconfig_<NAME>` (alias reconfig::<NAME>) from src/<NAME>/**/*.cpp, with the
#   public headers under include/reconfig/<NAME>/. New files are picked up without editing
#   CMake (CONFIGURE_DEPENDS), so modules can grow one concept per file.
function(reconfig_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${name}/*.cpp)
  set_property(GLOBAL APPEND PROPERTY RECONFIG_MODULES reconfig_${name})
  if(NOT sources)  # a module being started: headers only so far
    add_library(reconfig_${name} INTERFACE)
    add_library(reconfig::${name} ALIAS reconfig_${name})
    target_include_directories(reconfig_${name} INTERFACE ${CMAKE_SOURCE_DIR}/include)
    target_link_libraries(reconfig_${name} INTERFACE ${ARG_DEPENDS})
    return()
  endif()
  add_library(reconfig_${name} STATIC ${sources})
  add_library(reconfig::${name} ALIAS reconfig_${name})
  target_include_directories(reconfig_${name}
    PUBLIC ${CMAKE_SOURCE_DIR}/include
    PRIVATE ${CMAKE_SOURCE_DIR}/src)
  target_link_libraries(reconfig_${name} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  reconfig_set_warnings(reconfig_${name})
endfunction()

function(reconfig_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
    -Wno-deprecated-declarations)
endfunction()

# reconfig_add_tests(NAME DEPENDS <targets...>)
#   One GoogleTest executable `<NAME>_tests` from tests/<NAME>/*_test.cpp.
function(reconfig_add_tests name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/${name}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name}_tests ${sources})
  target_link_libraries(${name}_tests PRIVATE ${ARG_DEPENDS} reconfig_testing GTest::gtest GTest::gtest_main)
  reconfig_set_warnings(${name}_tests)
  # NO_PRETTY_VALUES: a parameterized test is named by its suite's name generator alone, not
  # followed by GetParam()'s printout (a byte dump of a struct, with pointers, for most).
  gtest_discover_tests(${name}_tests
    NO_PRETTY_VALUES
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
    PROPERTIES ENVIRONMENT "RECONFIG_SOURCE_DIR=${CMAKE_SOURCE_DIR};RECONFIG_BINARY_DIR=${CMAKE_BINARY_DIR}"
    DISCOVERY_TIMEOUT 60)
endfunction()
