#include "modeling/scene/scene.h"

namespace qacc {

std::vector<Light> Scene::defaultLights(const Camera& camera) {
  Light head;
  head.type = Light::Type::Directional;
  head.direction = camera.forward();
  head.color = {0.9, 0.9, 0.9};
  Light amb;
  amb.type = Light::Type::Ambient;
  amb.color = {0.1, 0.1, 0.1};
  return {head, amb};
}

}  // namespace qacc
