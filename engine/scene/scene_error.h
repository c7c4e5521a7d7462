#pragma once
// The one exception the scene module throws. Every message names the source
// (file path or "builtin:<name>") and the glTF field at fault, so a user can fix
// the asset without a debugger.

#include <stdexcept>
#include <string>

namespace eng::scene {

class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

} // namespace eng::scene
