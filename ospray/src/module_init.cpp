// The module's entry: ospLoadModule("revolve") finds libospray_module_revolve and calls this once;
// it registers the geometry type "revolution".
#include "Revolutions.h"

#include "ospray/version.h"

extern "C" OSPError OSPRAY_DLLEXPORT ospray_module_init_revolve(int16_t versionMajor, int16_t versionMinor,
                                                                int16_t /*versionPatch*/) {
  const OSPError status = ospray::moduleVersionCheck(versionMajor, versionMinor);
  if (status == OSP_NO_ERROR) ospray::Geometry::registerType<ospray::revolve_module::Revolutions>("revolution");
  return status;
}
