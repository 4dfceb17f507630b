#include "scene/module_keys.hpp"

namespace monosph {

namespace {
std::vector<ModuleKeys>& registry() {
  static std::vector<ModuleKeys> keys;
  return keys;
}
}  // namespace

void register_module_keys(ModuleKeys keys) {
  for (auto& k : registry())
    if (k.module == keys.module) return void(k = std::move(keys));
  registry().push_back(std::move(keys));
}

const std::vector<ModuleKeys>& registered_module_keys() {
  return registry();
}

}  // namespace monosph
