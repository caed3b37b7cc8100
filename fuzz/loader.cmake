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

# The loader under libFuzzer: 60 s of the smoke run. Coverage comes from the loader itself and,
# in a LINTEL_TINYGLTF_FROM_HEADER build, from tinygltf and stb (cmake/LintelThirdParty.cmake).
lintel_add_libfuzzer(NAME loader_libfuzzer SECONDS 60 MAX_LEN 65536
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/loader_libfuzzer.cpp ${CMAKE_CURRENT_SOURCE_DIR}/world_invariants.cpp
  LIBS lintel_scene INSTRUMENT lintel_scene)
