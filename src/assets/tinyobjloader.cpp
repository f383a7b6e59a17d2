// tinyobjloader compiled from Debian's header (libtinyobjloader-dev) in every
// build rather than linked as its shared library: the browser build cannot
// link one, and the sanitizers and the model fuzzer see inside the parser only
// when it is compiled with Atrium.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
