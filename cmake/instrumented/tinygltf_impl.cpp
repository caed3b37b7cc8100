// tinygltf's implementation, compiled inside a LINTEL_TINYGLTF_FROM_HEADER build (the sanitize
// stage) so that ASan, UBSan and libFuzzer coverage reach into it. Its default image loader calls
// stb_image, whose implementation is stb_impl.cpp.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
