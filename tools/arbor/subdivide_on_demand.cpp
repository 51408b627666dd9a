// `arbor`'s subdivide(): the module's, loaded on the first call. Linked into `arbor` only, ahead of the libraries,
// so the linker takes this definition and leaves generator/export/subdivide.cpp and OpenSubdiv out of the program
// (arbor-engine and the tests link the real one directly).
#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

#include "files/asset_folder.hpp"
#include "export/subdivide.hpp"
#include "subdivide_module.hpp"

namespace arbor {

namespace {

// Beside the program in the build tree; under PREFIX/lib/arbor once installed (the program in PREFIX/bin).
const SubdivideModule& loadModule() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path bin = programFolder();
  const fs::path folder = bin.empty() ? fs::path(".") : bin;
  std::string tried, why;
  for (const fs::path& file : {folder / kSubdivideModuleFile, folder.parent_path() / "lib" / "arbor" / kSubdivideModuleFile}) {
    tried += (tried.empty() ? "" : ", ") + file.string();
    if (!fs::exists(file, ec)) continue;
    void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      why = ::dlerror();
      continue;
    }
    using Entry = const SubdivideModule* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kSubdivideModuleEntry));
    const SubdivideModule* module = entry ? entry() : nullptr;
    if (module != nullptr && module->version == kSubdivideModuleVersion) return *module;  // kept loaded for the process
    why = file.string() + " is from another build of Arbor (no matching " + kSubdivideModuleEntry + ")";
    ::dlclose(handle);
  }
  throw std::runtime_error(std::string("--subdivide needs OpenSubdiv's module ") + kSubdivideModuleFile + ", installed with arbor; " +
                           (why.empty() ? "not found (looked for " + tried + ")" : why));
}

}  // namespace

QuadMesh subdivide(const QuadMesh& mesh, int levels, std::size_t maxQuads) {
  static std::once_flag once;
  static const SubdivideModule* module = nullptr;
  std::call_once(once, [] { module = &loadModule(); });  // a failed load throws, and the next call tries again
  return module->subdivide(mesh, levels, maxQuads);
}

}  // namespace arbor
