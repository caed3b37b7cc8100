# Fuzzing of `import doom`: a rapidcheck property test on a real map's records, directory and bytes
# (fuzz/doom_import_fuzz.cpp), run under ctest with a fixed seed (LINTEL_SOAK=1 for many more
# cases); it skips itself when Debian's freedoom package is not installed.
add_executable(doom_import_fuzz ${CMAKE_CURRENT_SOURCE_DIR}/doom_import_fuzz.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/world_invariants.cpp)
target_link_libraries(doom_import_fuzz PRIVATE lintel_scene rapidcheck)
target_include_directories(doom_import_fuzz PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)  # map_pwad.h
target_compile_options(doom_import_fuzz PRIVATE -UNDEBUG)
lintel_target_defaults(doom_import_fuzz)
set_target_properties(doom_import_fuzz PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
add_test(NAME doom_import_fuzz COMMAND doom_import_fuzz)
set_tests_properties(doom_import_fuzz PROPERTIES TIMEOUT 300 LABELS "fuzz;levels")
