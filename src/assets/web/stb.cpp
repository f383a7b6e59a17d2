// The stb functions Atrium calls, compiled from Debian's stb headers: the
// native build links Debian's libstb, which the WebAssembly build cannot, and
// the fuzz build compiles this in to see inside it.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_resize.h>
#include <stb_image_write.h>
