# tinygltf and stb: Debian's shared libraries by default, or (LINTEL_TINYGLTF_FROM_HEADER) compiled
# from Debian's headers inside this build, so that sanitizers and libFuzzer coverage see into them.
# Either way lintel_scene/lintel_render link `TinyGLTF::TinyGLTF` and `${LINTEL_STB_LIBRARY}`.
option(LINTEL_TINYGLTF_FROM_HEADER
       "Compile tinygltf and stb from their headers in this build (instrumented) instead of linking Debian's libraries" OFF)

if(NOT LINTEL_TINYGLTF_FROM_HEADER)
  find_package(TinyGLTF REQUIRED)
  return()
endif()

find_path(LINTEL_TINYGLTF_INCLUDE_DIR tiny_gltf.h REQUIRED)
find_path(LINTEL_STB_INCLUDE_DIR stb/stb_image.h REQUIRED)
# The implementations are third-party code: compiled with the build's sanitizer flags, without our
# warning set.
add_library(lintel_third_party_impl STATIC
  ${CMAKE_CURRENT_LIST_DIR}/instrumented/tinygltf_impl.cpp
  ${CMAKE_CURRENT_LIST_DIR}/instrumented/stb_impl.cpp)
target_include_directories(lintel_third_party_impl SYSTEM PRIVATE ${LINTEL_STB_INCLUDE_DIR}/stb)
target_include_directories(lintel_third_party_impl SYSTEM PUBLIC ${LINTEL_TINYGLTF_INCLUDE_DIR} ${LINTEL_STB_INCLUDE_DIR})
target_link_libraries(lintel_third_party_impl PRIVATE nlohmann_json::nlohmann_json)
target_compile_options(lintel_third_party_impl PRIVATE -w)
if(LINTEL_LIBFUZZER)
  # Coverage feedback inside tinygltf and stb as well as in the loader.
  target_compile_options(lintel_third_party_impl PRIVATE -fsanitize=fuzzer-no-link)
endif()

# Imported names, so that install(EXPORT) records a name and not this build-only target.
add_library(TinyGLTF::TinyGLTF INTERFACE IMPORTED)
set_target_properties(TinyGLTF::TinyGLTF PROPERTIES INTERFACE_LINK_LIBRARIES lintel_third_party_impl)
add_library(Lintel::stb_from_header INTERFACE IMPORTED)
set_target_properties(Lintel::stb_from_header PROPERTIES INTERFACE_LINK_LIBRARIES lintel_third_party_impl)
# find_library(LINTEL_STB_LIBRARY ...) in scene/ and render/ keeps a variable that is already set.
set(LINTEL_STB_LIBRARY Lintel::stb_from_header)
