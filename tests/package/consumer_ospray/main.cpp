// Loads the installed OSPRay module and picks a revolution: a cylinder of radius 1 around z, seen
// along +y from y = -5 through a perspective camera's centre, is hit at (0, -1, 0.5).
#include <ospray/ospray.h>
#include <ospray/ospray_util.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace {

void onError(void*, OSPError code, const char* message) {
  std::fprintf(stderr, "OSPRay error %d: %s\n", code, message);
}

}  // namespace

int main() {
  if (ospInit(nullptr, nullptr) != OSP_NO_ERROR) return 1;
  ospDeviceSetErrorCallback(ospGetCurrentDevice(), onError, nullptr);
  if (ospLoadModule("revolve") != OSP_NO_ERROR) {
    std::fprintf(stderr, "ospLoadModule(\"revolve\") failed\n");
    return 1;
  }
  const std::array<float, 8> profile = {0, 0, 1, 0, 1, 1, 0, 1};  // (r, z): disc, wall, lid
  OSPGeometry geometry = ospNewGeometry("revolution");
  OSPData data = ospNewSharedData(profile.data(), OSP_VEC2F, 4);
  ospSetObject(geometry, "profile", data);
  ospCommit(geometry);
  OSPGeometricModel model = ospNewGeometricModel(geometry);
  ospCommit(model);
  OSPGroup group = ospNewGroup();
  OSPData models = ospNewSharedData(&model, OSP_GEOMETRIC_MODEL, 1);
  ospSetObject(group, "geometry", models);
  ospCommit(group);
  OSPInstance instance = ospNewInstance(group);
  ospCommit(instance);
  OSPWorld world = ospNewWorld();
  OSPData instances = ospNewSharedData(&instance, OSP_INSTANCE, 1);
  ospSetObject(world, "instance", instances);
  ospCommit(world);
  OSPCamera camera = ospNewCamera("perspective");
  const std::array<float, 3> position = {0, -5, 0.5f}, direction = {0, 1, 0}, up = {0, 0, 1};
  ospSetParam(camera, "position", OSP_VEC3F, position.data());
  ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera, "up", OSP_VEC3F, up.data());
  ospCommit(camera);
  OSPRenderer renderer = ospNewRenderer("scivis");
  ospCommit(renderer);
  OSPFrameBuffer framebuffer = ospNewFrameBuffer(16, 16, OSP_FB_RGBA8, OSP_FB_COLOR);
  ospCommit(framebuffer);
  OSPPickResult pick;
  ospPick(&pick, framebuffer, renderer, camera, world, 0.5f, 0.5f);
  const bool ok = pick.hasHit && std::abs(pick.worldPosition[1] + 1.0f) < 1e-5f;
  std::printf("picked %s at (%g, %g, %g)\n", pick.hasHit ? "a hit" : "nothing", pick.worldPosition[0],
              pick.worldPosition[1], pick.worldPosition[2]);
  if (pick.hasHit) {
    ospRelease(pick.instance);
    ospRelease(pick.model);
  }
  for (OSPObject object : {OSPObject(framebuffer), OSPObject(renderer), OSPObject(camera), OSPObject(instances),
                           OSPObject(world), OSPObject(instance), OSPObject(models), OSPObject(group), OSPObject(model),
                           OSPObject(data), OSPObject(geometry)}) {
    ospRelease(object);
  }
  ospShutdown();
  return ok ? 0 : 1;
}
