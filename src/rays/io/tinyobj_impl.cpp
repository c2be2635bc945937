// tinyobjloader's implementation, compiled into rays_core from the Debian header (libtinyobjloader-dev)
// instead of linking its shared library: one C++ shared library fewer to load at every start of
// `rays`, and the fuzzers instrument it too.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
