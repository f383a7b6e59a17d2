// import_assimp for the WebAssembly build, which has no libassimp: FBX and
// the other formats it reads are refused with one line naming the way out.
#include "assets/assimp_import.hpp"

#include "assets/model_import.hpp"

namespace atrium::assets {

ModelImport import_assimp(const std::filesystem::path& path, AssetManager&, const ImportOptions&) {
  throw ImportError(path.string() + ": the browser build reads glTF and OBJ only (libassimp is native); convert the model to "
                    "glTF (`assimp export model.fbx model.gltf`)");
}

}  // namespace atrium::assets
