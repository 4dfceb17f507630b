#pragma once
// A physics module's scene keys (docs/architecture.md): the scene reader reads what is generic
// (name, phase, shape, material, initial fields, the shared SPH equations' keys) and hands each
// body's map, each material's map and the top level to every registered module, which reads its
// own keys into its own parameters.
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace monosph {

class MapReader;
struct BodySpec;
struct Material;
struct Scene;

// One module's parameters of one body, one material or the scene (its top-level section). A derived
// type names its module (`static constexpr const char* module`) and writes its values for `monosph
// info --config`.
struct ModuleParams {
  virtual ~ModuleParams() = default;
  virtual nlohmann::json dump() const = 0;
};

using ParamMap = std::map<std::string, std::shared_ptr<const ModuleParams>>;

// The parameters of module T::module in `params`, or T's defaults when it has none.
template <class T>
const T& module_params(const ParamMap& params) {
  static const T defaults{};
  auto it = params.find(T::module);
  return it == params.end() ? defaults : static_cast<const T&>(*it->second);
}

// How a module reads its keys; each reader is optional. A reader reads every key it knows, given
// or not (MapReader::optional marks an absent key as known, so that unknown-key detection and
// "did you mean" cover them), and returns the module's parameters (null: none).
// - read_body: the keys of one body, with `path` the body's key path; the generic keys of `body`
//   are already read, and so are the materials.
// - read_material: the keys of one material (`m`: its generic keys, already read; a module may
//   set m.reference_temperature); `preset`: the shipped material it starts from, or empty.
// - read_section: the module's top-level section(s) from the scene's map, after the bodies and
//   surfaces; it may switch its module on (s.modules).
struct ModuleKeys {
  std::string module;
  std::function<std::shared_ptr<const ModuleParams>(MapReader& b, const BodySpec& body,
                                                    const std::string& path, const Scene& s)>
      read_body = nullptr;
  std::function<std::shared_ptr<const ModuleParams>(MapReader& r, Material& m,
                                                    const std::string& preset)>
      read_material = nullptr;
  std::function<std::shared_ptr<const ModuleParams>(MapReader& root, Scene& s)> read_section =
      nullptr;
};

// Registers a module's keys (apps/assemble.cpp, register_modules); a second registration of
// the same module replaces the first.
void register_module_keys(ModuleKeys keys);
const std::vector<ModuleKeys>& registered_module_keys();

}  // namespace monosph
