#pragma once
// gmsh's C API (gmshc.h), loaded from libgmsh when a volume mesh is first asked for.
// Linking libgmsh into molsurf would load it and its eighty shared libraries into every
// run: 0.1 s and 44 MB before anything else, for a feature most runs do not use.
#include <gmshc.h>

#include <cstddef>
#include <string>
#include <type_traits>

namespace molsurf::volume_detail {

class GmshLibrary {
 public:
  // Loads libgmsh (throws molsurf::Error naming the package when it is missing).
  GmshLibrary();
  ~GmshLibrary();
  GmshLibrary(const GmshLibrary&) = delete;
  GmshLibrary& operator=(const GmshLibrary&) = delete;

  // f(args..., &ierr), throwing molsurf::Error with gmsh's last message when ierr != 0.
  template <class F, class... A>
  auto call(F f, A... args) const {
    int ierr = 0;
    if constexpr (std::is_void_v<std::invoke_result_t<F, A..., int*>>) {
      f(args..., &ierr);
      check(ierr);
    } else {
      auto result = f(args..., &ierr);
      check(ierr);
      return result;
    }
  }
  // gmsh's last error message, or "" (never throws).
  std::string last_error() const;

#define MOLSURF_GMSH_FUNCTION(name) decltype(&::name) name = nullptr;
  MOLSURF_GMSH_FUNCTION(gmshInitialize)
  MOLSURF_GMSH_FUNCTION(gmshFinalize)
  MOLSURF_GMSH_FUNCTION(gmshOptionSetNumber)
  MOLSURF_GMSH_FUNCTION(gmshLoggerStart)
  MOLSURF_GMSH_FUNCTION(gmshLoggerStop)
  MOLSURF_GMSH_FUNCTION(gmshLoggerGetLastError)
  MOLSURF_GMSH_FUNCTION(gmshModelAdd)
  MOLSURF_GMSH_FUNCTION(gmshModelAddDiscreteEntity)
  MOLSURF_GMSH_FUNCTION(gmshModelMeshAddNodes)
  MOLSURF_GMSH_FUNCTION(gmshModelMeshAddElementsByType)
  MOLSURF_GMSH_FUNCTION(gmshModelMeshCreateTopology)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoAddPoint)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoAddLine)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoAddCurveLoop)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoAddPlaneSurface)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoAddSurfaceLoop)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoAddVolume)
  MOLSURF_GMSH_FUNCTION(gmshModelGeoSynchronize)
  MOLSURF_GMSH_FUNCTION(gmshModelAddPhysicalGroup)
  MOLSURF_GMSH_FUNCTION(gmshModelSetPhysicalName)
  MOLSURF_GMSH_FUNCTION(gmshModelMeshGenerate)
  MOLSURF_GMSH_FUNCTION(gmshModelMeshGetNodes)
  MOLSURF_GMSH_FUNCTION(gmshModelMeshGetElementsByType)
  MOLSURF_GMSH_FUNCTION(gmshModelGetPhysicalGroups)
  MOLSURF_GMSH_FUNCTION(gmshModelGetPhysicalName)
  MOLSURF_GMSH_FUNCTION(gmshModelGetEntitiesForPhysicalGroup)
  MOLSURF_GMSH_FUNCTION(gmshFree)
#undef MOLSURF_GMSH_FUNCTION

 private:
  void check(int ierr) const;
  void* handle_ = nullptr;
};

// An array gmsh allocated for a result, freed with gmshFree.
template <class T>
struct GmshArray {
  const GmshLibrary& library;
  T* data = nullptr;
  std::size_t size = 0;
  explicit GmshArray(const GmshLibrary& l) : library(l) {}
  ~GmshArray() {
    if (data) library.gmshFree(data);
  }
  GmshArray(const GmshArray&) = delete;
  GmshArray& operator=(const GmshArray&) = delete;
  T operator[](std::size_t i) const { return data[i]; }
};

}  // namespace molsurf::volume_detail
