#include "materials/registry.hpp"

#include <fmt/format.h>

namespace camouflet {

Registry<EosFactory>& eos_registry() {
  static Registry<EosFactory> r;
  return r;
}
Registry<StrengthFactory>& strength_registry() {
  static Registry<StrengthFactory> r;
  return r;
}
Registry<DamageFactory>& damage_registry() {
  static Registry<DamageFactory> r;
  return r;
}
Registry<std::function<MaterialPreset()>>& preset_registry() {
  static Registry<std::function<MaterialPreset()>> r;
  return r;
}

namespace {

template <class Product, class Factory>
std::shared_ptr<const Product> build(Parameters& block, const Registry<Factory>& registry, const char* what) {
  const std::string type = block.string("type");
  const Factory* f = registry.find(type);
  if (!f) {
    const std::string guess = nearest(type, registry.names());
    block.fail("type", guess.empty()
                           ? fmt::format("unknown {} type '{}'; known: {}", what, type,
                                         fmt::join(registry.names(), ", "))
                           : fmt::format("unknown {} type '{}'; did you mean '{}'?", what, type, guess));
  }
  auto product = (*f)(block);
  block.finish();
  return product;
}

}  // namespace

std::shared_ptr<const EquationOfState> make_eos(Parameters& block) {
  return build<EquationOfState>(block, eos_registry(), "equation of state");
}
std::shared_ptr<const StrengthModel> make_strength(Parameters& block) {
  return build<StrengthModel>(block, strength_registry(), "strength model");
}
std::shared_ptr<const DamageModel> make_damage(Parameters& block) {
  return build<DamageModel>(block, damage_registry(), "damage model");
}

std::shared_ptr<const Material> make_material(const std::string& name, const std::string& preset,
                                              const SourceLocation& preset_where, Parameters eos,
                                              Parameters strength, Parameters damage) {
  if (!preset.empty()) {
    const auto* f = preset_registry().find(preset);
    if (!f) {
      const std::string guess = nearest(preset, preset_registry().names());
      throw InputError(preset_where,
                       guess.empty()
                           ? fmt::format("unknown material preset '{}'", preset)
                           : fmt::format("unknown material preset '{}'; did you mean '{}'?", preset, guess));
    }
    const MaterialPreset p = (*f)();
    eos.merge_defaults(p.eos);
    strength.merge_defaults(p.strength);
    damage.merge_defaults(p.damage);
  }
  if (!eos.has("type"))
    throw InputError(eos.where("type"), "material '" + name + "' needs an eos block with a type");
  auto e = make_eos(eos);
  for (Parameters* block : {&strength, &damage})
    if (!block->keys().empty() && !block->has("type"))
      block->fail("type", "a strength or damage block needs a 'type'");
  std::shared_ptr<const StrengthModel> s;
  if (strength.has("type")) s = make_strength(strength);
  std::shared_ptr<const DamageModel> d;
  if (damage.has("type")) d = make_damage(damage);
  return std::make_shared<const Material>(name, std::move(e), std::move(s), std::move(d));
}

}  // namespace camouflet
