#include "raster/osmesa/opencsg_glew.h"

#include <GL/glew.h>
// glew.h leaves GLAPI undefined, which osmesa.h needs.
#ifndef GLAPI
#define GLAPI extern
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

namespace qacc {

bool loadGlewForOpenCsg() {
  bool ok = true;
#define QACC_LOAD(name)                                                                       \
  __glew##name = reinterpret_cast<decltype(__glew##name)>(OSMesaGetProcAddress("gl" #name)); \
  ok = ok && __glew##name != nullptr;
  QACC_LOAD(BindFramebuffer)
  QACC_LOAD(BindRenderbuffer)
  QACC_LOAD(CheckFramebufferStatus)
  QACC_LOAD(DeleteFramebuffers)
  QACC_LOAD(DeleteRenderbuffers)
  QACC_LOAD(FramebufferRenderbuffer)
  QACC_LOAD(FramebufferTexture2D)
  QACC_LOAD(GenFramebuffers)
  QACC_LOAD(GenRenderbuffers)
  QACC_LOAD(RenderbufferStorage)
  QACC_LOAD(BeginQueryARB)
  QACC_LOAD(EndQueryARB)
  QACC_LOAD(GenQueriesARB)
  QACC_LOAD(DeleteQueriesARB)
  QACC_LOAD(GetQueryObjectuivARB)
  QACC_LOAD(BindProgramARB)
  QACC_LOAD(DeleteProgramsARB)
  QACC_LOAD(GenProgramsARB)
  QACC_LOAD(ProgramStringARB)
#undef QACC_LOAD
  // The extensions llvmpipe's compatibility profile offers and OpenCSG asks GLEW about.
  __GLEW_ARB_framebuffer_object = GL_TRUE;
  __GLEW_ARB_depth_texture = GL_TRUE;
  __GLEW_ARB_occlusion_query = GL_TRUE;
  __GLEW_ARB_texture_rectangle = GL_TRUE;
  __GLEW_ARB_texture_non_power_of_two = GL_TRUE;
  __GLEW_ARB_fragment_program = GL_TRUE;
  __GLEW_ARB_vertex_program = GL_TRUE;
  __GLEW_EXT_packed_depth_stencil = GL_TRUE;
  return ok;
}

}  // namespace qacc
