// OpenCSG on an OSMesa context (docs/CSG.md, "Triangles"). Debian's OpenCSG calls OpenGL
// extensions through GLEW's function pointers and extension flags, which glewInit()
// cannot fill in an OSMesa context (Debian's GLEW is built for GLX and fails with
// "Missing GL version"); this loads them through OSMesaGetProcAddress for the current
// context. Built only with OpenCSG (CMake QACC_HAVE_OPENCSG).
#pragma once

namespace qacc {

// For the current OSMesa context; false when a function OpenCSG needs is missing.
bool loadGlewForOpenCsg();

}  // namespace qacc
