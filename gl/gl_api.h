// The GL 4.5 core API as this backend sees it: prototypes, types and constants from Khronos'
// <GL/glcorearb.h>, resolved at link time against GLVND's libOpenGL (which exports every core
// entry point up to 4.5, so no loader table is needed; checked on Mesa 22.3).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
