// tinyobjloader's implementation compiled into the fuzz targets with the sanitizers and the
// coverage instrumentation, so that libFuzzer sees inside it. Its definitions take precedence
// over Debian's shared libtinyobjloader_double.
#define TINYOBJLOADER_USE_DOUBLE
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
