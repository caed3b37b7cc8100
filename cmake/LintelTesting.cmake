# lintel_add_test(NAME name SOURCES a.cpp... LIBS lib... [LABELS l...] [TIMEOUT s])
# One GoogleTest executable per test file group, registered with ctest. Asserts stay on in every
# build type for tests (NDEBUG removed), as in meshoptimizer.
function(lintel_add_test)
  cmake_parse_arguments(T "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  target_compile_options(${T_NAME} PRIVATE -UNDEBUG)
  target_compile_definitions(${T_NAME} PRIVATE LINTEL_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                LINTEL_BINARY_DIR="${PROJECT_BINARY_DIR}")
  lintel_target_defaults(${T_NAME})
  set_target_properties(${T_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  add_test(NAME ${T_NAME} COMMAND ${T_NAME})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  set_tests_properties(${T_NAME} PROPERTIES TIMEOUT ${T_TIMEOUT} LABELS "${T_LABELS}"
                       ENVIRONMENT "LINTEL_BIN=${PROJECT_BINARY_DIR}/bin/lintel")
endfunction()
