# Fuzzing of the scene loader: a rapidcheck property test that runs under ctest (a fixed seed and
# a few hundred cases; LINTEL_SOAK=1 for many more), and an optional libFuzzer target.
add_executable(loader_fuzz ${CMAKE_CURRENT_SOURCE_DIR}/loader_fuzz.cpp ${CMAKE_CURRENT_SOURCE_DIR}/world_invariants.cpp)
target_link_libraries(loader_fuzz PRIVATE lintel_scene rapidcheck nlohmann_json::nlohmann_json)
target_compile_definitions(loader_fuzz PRIVATE LINTEL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_compile_options(loader_fuzz PRIVATE -UNDEBUG)
lintel_target_defaults(loader_fuzz)
set_target_properties(loader_fuzz PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
add_test(NAME loader_fuzz COMMAND loader_fuzz)
set_tests_properties(loader_fuzz PROPERTIES TIMEOUT 120 LABELS "fuzz;scene")

option(LINTEL_LIBFUZZER "Build the libFuzzer scene-loader target (needs clang)" OFF)
if(LINTEL_LIBFUZZER)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "LINTEL_LIBFUZZER needs clang: configure with CXX=clang++-14")
  endif()
  # Coverage feedback needs the loader itself instrumented, not only the entry point.
  target_compile_options(lintel_scene PRIVATE -fsanitize=fuzzer-no-link)
  add_executable(loader_libfuzzer ${CMAKE_CURRENT_SOURCE_DIR}/loader_libfuzzer.cpp
                                  ${CMAKE_CURRENT_SOURCE_DIR}/world_invariants.cpp)
  target_link_libraries(loader_libfuzzer PRIVATE lintel_scene)
  target_compile_options(loader_libfuzzer PRIVATE -fsanitize=fuzzer,address,undefined)
  target_link_options(loader_libfuzzer PRIVATE -fsanitize=fuzzer,address,undefined)
  lintel_target_defaults(loader_libfuzzer)
endif()
