# Property tests of the visibility core on generated scenes (rapidcheck + Embree ground truth).
add_executable(visibility_properties
  ${CMAKE_CURRENT_SOURCE_DIR}/visibility_properties.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/world_pool.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/camera_samples.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/dynamic_properties.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/mover_properties.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/link_properties.cpp)
target_link_libraries(visibility_properties PRIVATE lintel_visibility lintel_scene lintel_groundtruth lintel_test_worlds rapidcheck)
target_include_directories(visibility_properties PRIVATE ${PROJECT_SOURCE_DIR}/tests/visibility)
target_compile_options(visibility_properties PRIVATE -UNDEBUG)
lintel_target_defaults(visibility_properties)
set_target_properties(visibility_properties PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
add_test(NAME visibility_properties COMMAND visibility_properties)
set_tests_properties(visibility_properties PROPERTIES TIMEOUT 900 LABELS "fuzz;visibility")
