# Camera timelines under libFuzzer (timeline_libfuzzer.cpp): 30 s of the smoke run. White-box: it
# calls the scene library's JSON timeline reader (scene/src) directly.
lintel_add_libfuzzer(NAME timeline_libfuzzer SECONDS 30 MAX_LEN 4096
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/timeline_libfuzzer.cpp ${CMAKE_CURRENT_SOURCE_DIR}/world_invariants.cpp
  LIBS lintel_scene nlohmann_json::nlohmann_json INSTRUMENT lintel_scene lintel_visibility)
if(TARGET timeline_libfuzzer)
  target_include_directories(timeline_libfuzzer PRIVATE ${PROJECT_SOURCE_DIR}/scene/src)
endif()
