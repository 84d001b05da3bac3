// ViewCulling: whether the loader models only what the view shows, and for which image.
// With it on (the default), a top-level object's pieces whose conservative bounds miss the
// view volume (scene/view_volume.h) are not emitted: the modelers whose build is costly test
// their cells before building them (ObjectContext::view), and the loader drops any other
// primitive whose exact world bounds (geometry/primitive_bounds.h) miss the volume. Culling
// never opens a hole: the culled scene renders pixel-identically to the unculled one at
// that image size (tests/tools/test_view_culling.cpp). Parts of `csg` objects are never
// culled (a tree's leaves stay whole).
//
// The volume depends on the image's aspect ratio: a command that renders at another size
// than the scene file's (--width/--height) passes that size here, so the scene is culled
// against the view it is drawn with. `--no-view-cull` (every command that loads a scene)
// turns it off.
#pragma once

namespace qacc {

struct ViewCulling {
  bool enabled = true;
  int width = 0, height = 0;  // the image size the scene is rendered at; 0 and 0: the file's own
};

}  // namespace qacc
