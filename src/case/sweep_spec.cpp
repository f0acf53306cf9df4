#include "case/sweep_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

#include "case/buried_structure_params.hpp"
#include "case/toml_reader.hpp"

namespace camouflet {

namespace {

// A generator key with the value given to it and where the sweep file says so.
struct Setting {
  std::string key;  // dotted generator key
  const toml::node* value = nullptr;
  SourceLocation where;
};

// Leaves of a table as dotted keys: `charge.mass = 1` and `"charge.mass" = 1`
// and `[grid.charge] mass = 1` all give "charge.mass". Arrays are leaves.
void flatten(const toml::table& table, const std::string& prefix, const std::string& file,
             const std::string& path, std::vector<Setting>& out) {
  for (const auto& [name, value] : table) {
    const std::string key = prefix.empty() ? std::string(name.str()) : prefix + "." + std::string(name.str());
    if (const toml::table* t = value.as_table())
      flatten(*t, key, file, path, out);
    else
      out.push_back({key, &value, location_of(value, file, path + "." + key)});
  }
}

std::string text_of(const toml::node& v) {
  if (const auto* s = v.as_string()) return s->get();
  if (const auto* i = v.as_integer()) return fmt::format("{}", i->get());
  if (const auto* d = v.as_floating_point()) return fmt::format("{}", d->get());
  if (const auto* b = v.as_boolean()) return b->get() ? "true" : "false";
  std::ostringstream os;
  os << toml::toml_formatter(v);
  return os.str();
}

bool is_scalar(const toml::node& v) {
  return v.is_string() || v.is_integer() || v.is_floating_point() || v.is_boolean();
}

// Sets `key` (dotted) of `params` to a copy of `value`, creating tables on the way.
void assign(toml::table& params, const Setting& s) {
  toml::table* t = &params;
  std::string rest = s.key;
  for (std::size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1)) {
    const std::string part = rest.substr(0, dot);
    toml::node* n = t->get(part);
    if (!n) n = &t->insert_or_assign(part, toml::table{}).first->second;
    t = n->as_table();
    if (!t) throw InputError(s.where, fmt::format("'{}' is a value in the base file, not a table", part));
  }
  s.value->visit([&](const auto& v) { t->insert_or_assign(rest, v); });
}

bool valid_name(const std::string& n) {
  // The sweep's own files share the output folder with the case folders.
  for (const char* reserved : {"", ".", "..", "sweep.toml", "cases.csv", "sweep.csv", "sweep.png"})
    if (n == reserved) return false;
  for (char c : n)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
  return true;
}

// The generator's verdict on one case; its errors are moved to the sweep
// file's line of the setting they concern.
void check_case(const SweepSpec& sweep, const SweepCase& c, const std::vector<Setting>& settings) {
  try {
    read_buried_structure_params_text(sweep_case_params_text(sweep, c), sweep.base);
  } catch (const InputError& e) {
    const std::string& k = e.where().key;
    for (const Setting& s : settings)
      if (!k.empty() && (s.key == k || s.key.starts_with(k + ".") || k.starts_with(s.key + ".")))
        throw InputError(s.where, fmt::format("case '{}': {}", c.name, e.message()));
    SourceLocation w{sweep.file.string(), 0, 0, k};
    throw InputError(w, fmt::format("case '{}' (base {} with this sweep's values): {}", c.name,
                                    sweep.base.string(), e.message()));
  }
}

}  // namespace

std::string sweep_case_params_text(const SweepSpec& sweep, const SweepCase& c) {
  std::ostringstream os;
  os << "# Case '" << c.name << "' of the sweep " << sweep.file.string() << " (camouflet sweep):\n"
     << "# the base " << sweep.base.string() << " with the sweep's [set] values";
  for (std::size_t k = 0; k < sweep.varied_keys.size(); ++k)
    if (!c.values[k].empty()) os << ", " << sweep.varied_keys[k] << " = " << c.values[k];
  os << ".\n\n" << toml::toml_formatter(c.params) << '\n';
  return os.str();
}

SweepSpec read_sweep_text(const std::string& text, const std::filesystem::path& file) {
  const std::string f = file.string();
  toml::table doc;
  try {
    doc = toml::parse(text, f);
  } catch (const toml::parse_error& e) {
    SourceLocation w{f, static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column),
                     ""};
    throw InputError(w, fmt::format("malformed TOML: {}", e.description()));
  }
  SweepSpec sweep;
  sweep.file = file;
  TomlReader root(doc, f, "");
  sweep.title = root.string("title", "");
  const std::string base = root.string("base");
  sweep.base = file.parent_path() / base;
  toml::table base_doc;
  {
    std::ifstream in(sweep.base, std::ios::binary);
    if (!in) root.fail("base", fmt::format("cannot open the base parameter file {}", sweep.base.string()));
    std::stringstream base_text;
    base_text << in.rdbuf();
    // The base must be a valid parameter file on its own; its errors name the base file.
    read_buried_structure_params_text(base_text.str(), sweep.base);
    base_doc = toml::parse(base_text.str(), sweep.base.string());
  }

  std::vector<Setting> common;
  if (const toml::node* n = root.node("set")) {
    if (!n->is_table()) root.fail("set", "expected a table of generator keys and values");
    flatten(*n->as_table(), "", f, "set", common);
    for (Setting& s : common) {
      s.where.key = s.key;
      if (!is_scalar(*s.value)) throw InputError(s.where, "expected a number, a string or a boolean");
    }
  }
  const toml::node* grid = root.node("grid");
  const toml::node* list = root.node("case");
  if (grid && list) root.fail("case", "give either [grid] or [[case]] tables, not both");
  if (!grid && !list) root.fail("grid", "a sweep needs a [grid] table or [[case]] tables to vary");
  const auto refuse_common = [&](const Setting& s) {
    for (const Setting& c : common)
      if (c.key == s.key || c.key.starts_with(s.key + ".") || s.key.starts_with(c.key + "."))
        throw InputError(s.where, fmt::format("'{}' is also given in [set] (line {})", c.key, c.where.line));
  };

  std::vector<std::vector<Setting>> case_settings;
  std::vector<std::string> names;
  if (grid) {
    if (!grid->is_table()) root.fail("grid", "expected a table: generator key = [values]");
    std::vector<Setting> axes;
    flatten(*grid->as_table(), "", f, "grid", axes);
    if (axes.empty()) root.fail("grid", "empty grid: give at least one key = [values]");
    std::vector<std::vector<Setting>> values;
    for (Setting& axis : axes) {
      axis.where.key = axis.key;
      refuse_common(axis);
      const toml::array* a = axis.value->as_array();
      if (!a) throw InputError(axis.where, "expected a list of values to vary over");
      if (a->empty()) throw InputError(axis.where, "empty list: give at least one value");
      std::vector<Setting>& v = values.emplace_back();
      for (const toml::node& item : *a) {
        SourceLocation w = location_of(item, f, axis.key);
        if (!is_scalar(item)) throw InputError(w, "expected a number, a string or a boolean");
        v.push_back({axis.key, &item, w});
      }
      sweep.varied_keys.push_back(axis.key);
    }
    // Every combination, the last key varying fastest.
    std::vector<std::size_t> index(values.size(), 0);
    for (bool more = true; more;) {
      std::vector<Setting>& c = case_settings.emplace_back();
      for (std::size_t k = 0; k < values.size(); ++k) c.push_back(values[k][index[k]]);
      more = false;
      for (std::size_t k = values.size(); k-- > 0;) {
        if (++index[k] < values[k].size()) {
          more = true;
          break;
        }
        index[k] = 0;
      }
    }
    const int width = static_cast<int>(fmt::format("{}", case_settings.size()).size());
    for (std::size_t i = 0; i < case_settings.size(); ++i)
      names.push_back(fmt::format("case_{:0{}}", i + 1, width));
  } else {
    const toml::array* a = list->as_array();
    if (!a || !a->is_array_of_tables())
      root.fail("case", "expected [[case]] tables of generator key = value");
    if (a->empty()) root.fail("case", "empty list: give at least one [[case]]");
    const int width = static_cast<int>(fmt::format("{}", a->size()).size());
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table& t = *(*a)[i].as_table();
      const std::string path = fmt::format("case[{}]", i);
      std::string name = fmt::format("case_{:0{}}", i + 1, width);
      std::vector<Setting> settings;
      flatten(t, "", f, path, settings);
      std::vector<Setting> kept;
      for (Setting& s : settings) {
        if (s.key == "name") {
          if (!s.value->is_string() || !valid_name(s.value->as_string()->get()))
            throw InputError(
                s.where,
                "expected a folder name of letters, digits, '_', '-' and '.' (not one of the sweep's "
                "files sweep.toml, cases.csv, sweep.csv, sweep.png)");
          name = s.value->as_string()->get();
          continue;
        }
        s.where.key = s.key;
        if (!is_scalar(*s.value)) throw InputError(s.where, "expected a number, a string or a boolean");
        refuse_common(s);
        if (std::find(sweep.varied_keys.begin(), sweep.varied_keys.end(), s.key) == sweep.varied_keys.end())
          sweep.varied_keys.push_back(s.key);
        kept.push_back(s);
      }
      for (const std::string& other : names)
        if (other == name)
          throw InputError(location_of(t, f, path), fmt::format("duplicate case name '{}'", name));
      names.push_back(name);
      case_settings.push_back(std::move(kept));
    }
  }
  root.finish();

  for (std::size_t i = 0; i < case_settings.size(); ++i) {
    SweepCase c;
    c.name = names[i];
    c.params = base_doc;
    c.values.assign(sweep.varied_keys.size(), "");
    for (const Setting& s : common) assign(c.params, s);
    for (const Setting& s : case_settings[i]) {
      assign(c.params, s);
      const auto k = std::find(sweep.varied_keys.begin(), sweep.varied_keys.end(), s.key);
      c.values[static_cast<std::size_t>(k - sweep.varied_keys.begin())] = text_of(*s.value);
    }
    std::vector<Setting> all = common;
    all.insert(all.end(), case_settings[i].begin(), case_settings[i].end());
    sweep.cases.push_back(std::move(c));
    check_case(sweep, sweep.cases.back(), all);
  }
  return sweep;
}

SweepSpec read_sweep(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string(), 0, 0, ""}, "cannot open the sweep file");
  std::stringstream text;
  text << in.rdbuf();
  return read_sweep_text(text.str(), file);
}

}  // namespace camouflet
