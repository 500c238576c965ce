// The one translation unit that compiles tinyobjloader (header-only; Debian's libtinyobjloader-dev).
// TINYOBJLOADER_USE_DOUBLE comes from CMake so every TU sees the same real_t.
#define TINYOBJLOADER_IMPLEMENTATION
#include "tiny_obj_loader.h"
