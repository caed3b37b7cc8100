// stb_image and stb_image_write, compiled inside a LINTEL_TINYGLTF_FROM_HEADER build instead of
// Debian's libstb.so, so that the PNG/JPEG decoding of textures runs instrumented.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
