# Property tests of portal+hiz's occlusion on generated scenes and camera paths (rapidcheck +
# Embree ground truth); needs the reference targets (LINTEL_BUILD_REFERENCES).
if(TARGET lintel_accuracy)
  add_executable(hiz_properties ${CMAKE_CURRENT_SOURCE_DIR}/hiz_properties.cpp)
  target_link_libraries(hiz_properties PRIVATE lintel_accuracy lintel_scene lintel_groundtruth rapidcheck)
  target_compile_options(hiz_properties PRIVATE -UNDEBUG)
  lintel_target_defaults(hiz_properties)
  set_target_properties(hiz_properties PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  add_test(NAME hiz_properties COMMAND hiz_properties)
  set_tests_properties(hiz_properties PROPERTIES TIMEOUT 300 LABELS "fuzz;accuracy")
endif()
