#pragma once
// A physics module's scene keys (docs/architecture.md): the scene reader reads what is generic
// (name, phase, shape, material, initial fields, the shared SPH equations' keys) and hands each
// body's map to every registered module, which reads its own keys into its own parameters.
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace monosph {

class MapReader;
struct BodySpec;
struct Scene;

// One module's parameters of one body. A derived type names its module (`static constexpr
// const char* module`) and writes its values for `monosph info --config`.
struct BodyParams {
  virtual ~BodyParams() = default;
  virtual nlohmann::json dump() const = 0;
};

using BodyParamMap = std::map<std::string, std::shared_ptr<const BodyParams>>;

// The parameters of module T::module, or T's defaults when the body has none.
template <class T>
const T& body_params(const BodyParamMap& params) {
  static const T defaults{};
  auto it = params.find(T::module);
  return it == params.end() ? defaults : static_cast<const T&>(*it->second);
}

// How a module reads its keys. `read_body` reads the module's keys of one body from the body's
// map (every key it knows, given or not: MapReader::optional marks an absent key as known, so
// that unknown-key detection and "did you mean" cover them), with `path` the body's key path;
// the generic keys of `body` are already read.
struct ModuleKeys {
  std::string module;
  std::function<std::shared_ptr<const BodyParams>(MapReader& b, const BodySpec& body,
                                                  const std::string& path, const Scene& s)>
      read_body;
};

// Registers a module's keys (apps/assemble.cpp, register_modules); a second registration of
// the same module replaces the first.
void register_module_keys(ModuleKeys keys);
const std::vector<ModuleKeys>& registered_module_keys();

}  // namespace monosph
