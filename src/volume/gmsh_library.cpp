#include "volume/gmsh_library.hpp"

#include <dlfcn.h>

#include "molsurf/error.hpp"

namespace molsurf::volume_detail {

GmshLibrary::GmshLibrary() {
  // The versioned name first: the one the headers we were built with belong to.
  for (const char* name : {"libgmsh.so.4.8", "libgmsh.so"}) {
    handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (handle_) break;
  }
  if (!handle_)
    throw Error("the volume mesh needs gmsh's library, which is not installed (Debian: libgmsh4.8, or libgmsh-dev)");
  auto resolve = [this](auto& function, const char* name) {
    function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(handle_, name));
    if (!function) throw Error(std::string("the installed gmsh library has no ") + name + ": it is not the 4.x API");
  };
#define MOLSURF_GMSH_RESOLVE(name) resolve(name, #name);
  MOLSURF_GMSH_RESOLVE(gmshInitialize)
  MOLSURF_GMSH_RESOLVE(gmshFinalize)
  MOLSURF_GMSH_RESOLVE(gmshOptionSetNumber)
  MOLSURF_GMSH_RESOLVE(gmshLoggerStart)
  MOLSURF_GMSH_RESOLVE(gmshLoggerStop)
  MOLSURF_GMSH_RESOLVE(gmshLoggerGetLastError)
  MOLSURF_GMSH_RESOLVE(gmshModelAdd)
  MOLSURF_GMSH_RESOLVE(gmshModelAddDiscreteEntity)
  MOLSURF_GMSH_RESOLVE(gmshModelMeshAddNodes)
  MOLSURF_GMSH_RESOLVE(gmshModelMeshAddElementsByType)
  MOLSURF_GMSH_RESOLVE(gmshModelMeshCreateTopology)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoAddPoint)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoAddLine)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoAddCurveLoop)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoAddPlaneSurface)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoAddSurfaceLoop)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoAddVolume)
  MOLSURF_GMSH_RESOLVE(gmshModelGeoSynchronize)
  MOLSURF_GMSH_RESOLVE(gmshModelAddPhysicalGroup)
  MOLSURF_GMSH_RESOLVE(gmshModelSetPhysicalName)
  MOLSURF_GMSH_RESOLVE(gmshModelMeshGenerate)
  MOLSURF_GMSH_RESOLVE(gmshModelMeshGetNodes)
  MOLSURF_GMSH_RESOLVE(gmshModelMeshGetElementsByType)
  MOLSURF_GMSH_RESOLVE(gmshModelGetPhysicalGroups)
  MOLSURF_GMSH_RESOLVE(gmshModelGetPhysicalName)
  MOLSURF_GMSH_RESOLVE(gmshModelGetEntitiesForPhysicalGroup)
  MOLSURF_GMSH_RESOLVE(gmshFree)
#undef MOLSURF_GMSH_RESOLVE
}

GmshLibrary::~GmshLibrary() {
  // Left loaded: gmsh registers handlers and static objects that unloading would cut off.
}

std::string GmshLibrary::last_error() const {
  char* text = nullptr;
  int ierr = 0;
  gmshLoggerGetLastError(&text, &ierr);
  std::string message = ierr == 0 && text ? text : "";
  if (text) gmshFree(text);
  return message;
}

void GmshLibrary::check(int ierr) const {
  if (ierr == 0) return;
  const std::string why = last_error();
  throw Error("volume mesh: gmsh failed" + (why.empty() ? std::string() : ": " + why));
}

}  // namespace molsurf::volume_detail
