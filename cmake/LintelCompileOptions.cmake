# Warnings, -Werror in CI and the sanitizer option, applied per target by lintel_target_defaults().
function(lintel_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wno-missing-field-initializers)
  # GCC 12 reports -Wrestrict inside libstdc++ for `"literal" + std::string` at -O3 (GCC bug
  # 105329, a false positive in its own headers); it would fail every -Werror Release build.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(LINTEL_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

if(LINTEL_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# The sanitize stage's LD_PRELOAD library (scripts/sanitizer/keep_modules_loaded.cpp): without
# sanitizer flags, so that uninstrumented child processes can load it too.
if(LINTEL_SANITIZE)
  add_library(lintel_keep_modules_loaded SHARED ${PROJECT_SOURCE_DIR}/scripts/sanitizer/keep_modules_loaded.cpp)
  target_compile_options(lintel_keep_modules_loaded PRIVATE -fno-sanitize=all)
  target_link_options(lintel_keep_modules_loaded PRIVATE -fno-sanitize=all)
endif()

# One target for everything the sanitize stage runs (scripts/lib/sanitize passes the list after a
# first configure): a single make goal builds its dependencies in parallel, several goals do not.
if(LINTEL_SANITIZE_STAGE_TARGETS)
  add_custom_target(lintel_sanitize_stage)
  add_dependencies(lintel_sanitize_stage ${LINTEL_SANITIZE_STAGE_TARGETS})
endif()
