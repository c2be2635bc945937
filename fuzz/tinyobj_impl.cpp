// tinyobjloader's implementation, compiled here from the Debian header (libtinyobjloader-dev) so that
// the fuzzers instrument it too (the shared library the main build links is not instrumented).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
