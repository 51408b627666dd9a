// The subdivision module's one entry: generator/export/subdivide.cpp, compiled into it, behind a table.
#include "subdivide_module.hpp"

#include "export/subdivide.hpp"

extern "C" __attribute__((visibility("default"))) const arbor::SubdivideModule* arborSubdivideModule() {
  static const arbor::SubdivideModule module{arbor::kSubdivideModuleVersion, &arbor::subdivide};
  return &module;
}
