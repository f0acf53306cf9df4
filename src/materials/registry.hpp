#pragma once
// Name -> factory registries for EOS, strength and damage models, and named
// material presets. Each model registers its keyword in its own .cpp file:
//
//   CAMOUFLET_REGISTER_EOS("linear", make_linear_eos);
//
// so that adding a model touches only new files (style.md #3). The materials
// library is linked whole-archive so these static registrations survive.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/parameters.hpp"
#include "materials/material.hpp"

namespace camouflet {

using EosFactory = std::function<std::shared_ptr<const EquationOfState>(Parameters&)>;
using StrengthFactory = std::function<std::shared_ptr<const StrengthModel>(Parameters&)>;
using DamageFactory = std::function<std::shared_ptr<const DamageModel>(Parameters&)>;

// A preset is the parameters of each block (with its `type`), exactly as a
// case file would give them; user keys given beside `preset = "..."` override.
struct MaterialPreset {
  std::string description;  // with the source: "Wang et al. 2005, Table 5"
  Parameters eos;
  Parameters strength;  // empty (no "type") for a fluid
  Parameters damage;    // empty when none
};

template <class Factory>
class Registry {
 public:
  bool add(const std::string& name, Factory f) {
    entries_[name] = std::move(f);
    return true;
  }
  const Factory* find(const std::string& name) const {
    auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : &it->second;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const auto& [k, v] : entries_) n.push_back(k);
    return n;
  }

 private:
  std::map<std::string, Factory> entries_;
};

Registry<EosFactory>& eos_registry();
Registry<StrengthFactory>& strength_registry();
Registry<DamageFactory>& damage_registry();
Registry<std::function<MaterialPreset()>>& preset_registry();

// Build each component from a parameter block whose "type" names the model.
// Unknown types and unused keys throw InputError naming the key (with a
// "did you mean" suggestion).
std::shared_ptr<const EquationOfState> make_eos(Parameters& block);
std::shared_ptr<const StrengthModel> make_strength(Parameters& block);
std::shared_ptr<const DamageModel> make_damage(Parameters& block);

// A whole material from its three blocks (strength/damage blocks may be
// empty). `preset` names a registered preset laid under the blocks ("" none).
std::shared_ptr<const Material> make_material(const std::string& name, const std::string& preset,
                                              const SourceLocation& preset_where, Parameters eos,
                                              Parameters strength, Parameters damage);

}  // namespace camouflet

#define CAMOUFLET_CONCAT_INNER(a, b) a##b
#define CAMOUFLET_CONCAT(a, b) CAMOUFLET_CONCAT_INNER(a, b)
#define CAMOUFLET_REGISTER_EOS(name, factory)                               \
  static const bool CAMOUFLET_CONCAT(camouflet_eos_registered_, __LINE__) = \
      ::camouflet::eos_registry().add(name, factory)
#define CAMOUFLET_REGISTER_STRENGTH(name, factory)                               \
  static const bool CAMOUFLET_CONCAT(camouflet_strength_registered_, __LINE__) = \
      ::camouflet::strength_registry().add(name, factory)
#define CAMOUFLET_REGISTER_DAMAGE(name, factory)                               \
  static const bool CAMOUFLET_CONCAT(camouflet_damage_registered_, __LINE__) = \
      ::camouflet::damage_registry().add(name, factory)
#define CAMOUFLET_REGISTER_PRESET(name, factory)                               \
  static const bool CAMOUFLET_CONCAT(camouflet_preset_registered_, __LINE__) = \
      ::camouflet::preset_registry().add(name, factory)
