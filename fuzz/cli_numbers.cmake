# The command line's numbers under libFuzzer (cli_numbers_libfuzzer.cpp): 30 s of the smoke run.
# It compiles the CLI's option and parsing files (none has main()) into the target itself, so they
# are instrumented with it.
set(_cli ${PROJECT_SOURCE_DIR}/apps/lintel)
lintel_add_libfuzzer(NAME cli_numbers_libfuzzer SECONDS 30 MAX_LEN 512
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/cli_numbers_libfuzzer.cpp ${_cli}/cli_common.cpp ${_cli}/visibility_args.cpp
          ${_cli}/render_args.cpp ${_cli}/resource_budget.cpp
  LIBS lintel_scene lintel_visibility lintel_render CLI11::CLI11 nlohmann_json::nlohmann_json
  INSTRUMENT lintel_visibility)
if(TARGET cli_numbers_libfuzzer)
  target_include_directories(cli_numbers_libfuzzer PRIVATE ${_cli})
endif()
