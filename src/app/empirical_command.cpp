// `camouflet empirical`: TM 5-855-1 free-field ground shock at given ranges and
// the in-structure shock averaged over a structure's span (Wang et al. 2005
// §5.3, §5.5; src/empirical, docs/theory/tm5-855-1.md). Values are read as text
// and checked here, so that every bad value exits with status 2 and names its
// option (docs/exit-codes.md).
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "empirical/ground_shock.hpp"
#include "empirical/imperial_units.hpp"
#include "empirical/shock_peaks.hpp"

namespace camouflet::app {

namespace {

using namespace camouflet::empirical;

// The options as typed.
struct EmpiricalArguments {
  std::string charge_mass;
  std::string coupling = "1";
  std::string law = "wang2005";
  std::vector<std::string> attenuation;
  std::vector<std::string> ranges;
  std::vector<std::string> span;
  std::string soil_density;
  std::string seismic_velocity;
  bool csv = false;
};

// The options checked and converted.
struct EmpiricalRequest {
  Charge charge;
  std::vector<GroundShockLaw> laws;  // one per attenuation coefficient
  std::vector<double> ranges;        // m
  bool has_span = false;
  double span_near = 0.0;  // m
  double span_far = 0.0;   // m
  bool csv = false;
};

// A bad value of a named option.
class OptionError : public std::runtime_error {
 public:
  OptionError(const std::string& option, const std::string& message)
      : std::runtime_error(option + ": " + message) {}
};

double parse_number(const std::string& option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw OptionError(option, fmt::format("'{}' is not a finite number", text));
  return v;
}

double parse_positive(const std::string& option, const std::string& text) {
  const double v = parse_number(option, text);
  if (!(v > 0.0)) throw OptionError(option, fmt::format("must be positive, got {}", text));
  return v;
}

EmpiricalRequest check(const EmpiricalArguments& a) {
  EmpiricalRequest r;
  if (a.charge_mass.empty()) throw OptionError("--charge-mass", "is required (kg of TNT)");
  r.charge.mass = parse_positive("--charge-mass", a.charge_mass);
  r.charge.coupling = parse_number("--coupling", a.coupling);
  if (!(r.charge.coupling > 0.0 && r.charge.coupling <= 1.0))
    throw OptionError("--coupling", fmt::format("must lie in (0, 1], got {}", a.coupling));

  for (const auto& text : a.ranges) r.ranges.push_back(parse_positive("--range", text));
  if (!a.span.empty()) {
    if (a.span.size() != 2)
      throw OptionError("--span", fmt::format("takes two ranges R1 R2 (m), got {} value(s)", a.span.size()));
    r.span_near = parse_positive("--span", a.span[0]);
    r.span_far = parse_positive("--span", a.span[1]);
    if (!(r.span_far > r.span_near))
      throw OptionError("--span", fmt::format("R2 must exceed R1, got {} .. {}", a.span[0], a.span[1]));
    r.has_span = true;
  }
  if (r.ranges.empty() && !r.has_span)
    throw OptionError("--range/--span",
                      "give ranges for free-field peaks, a span for in-structure shock, or both");

  std::vector<double> ns;
  for (const auto& text : a.attenuation) ns.push_back(parse_positive("--attenuation", text));
  if (ns.empty()) ns = {2.0, 2.5};  // the paper's bounds for its sandy clay (Wang et al. 2005, Table 1)

  if (a.law == "wang2005") {
    if (!a.soil_density.empty())
      throw OptionError("--soil-density",
                        "is used only by --law tm5 (wang2005 has the paper's soil built in)");
    if (!a.seismic_velocity.empty())
      throw OptionError("--seismic-velocity",
                        "is used only by --law tm5 (wang2005 has the paper's soil built in)");
    for (double n : ns) {
      if (std::abs(n - 2.0) > 1e-12 && std::abs(n - 2.5) > 1e-12)
        throw OptionError("--attenuation",
                          fmt::format("--law wang2005 has coefficients only for n = 2 and 2.5, "
                                      "got {}; use --law tm5 for other values",
                                      n));
      r.laws.push_back(wang2005(n));
    }
  } else if (a.law == "tm5") {
    Soil soil = wang2005_sandy_clay();
    if (!a.soil_density.empty()) soil.density = parse_positive("--soil-density", a.soil_density);
    if (!a.seismic_velocity.empty())
      soil.seismic_velocity = parse_positive("--seismic-velocity", a.seismic_velocity);
    for (double n : ns) r.laws.push_back(tm5_855_1(soil, n));
  } else {
    throw OptionError("--law", fmt::format("must be 'wang2005' or 'tm5', got '{}'", a.law));
  }
  r.csv = a.csv;
  return r;
}

// Four significant digits at most, never in exponent form between 1e-6 and 1e9.
std::string significant(double x) {
  if (x == 0.0 || !std::isfinite(x)) return fmt::format("{}", x);
  const int magnitude = static_cast<int>(std::floor(std::log10(std::abs(x))));
  if (magnitude < -6 || magnitude > 9) return fmt::format("{:.3e}", x);
  std::string text = fmt::format("{:.{}f}", x, std::max(0, 3 - magnitude));
  // Trailing zeros would claim digits the table does not mean: 1.59, not 1.590.
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

constexpr double MPa = 1e6;
constexpr double mm = 1e-3;
const double g = imperial::standard_gravity;

void print_table(const EmpiricalRequest& r) {
  const double w_cbrt = std::cbrt(r.charge.mass);
  fmt::print("TM 5-855-1 free-field ground shock (Wang et al. 2005 §5.3, §5.5)\n");
  fmt::print("  charge mass W = {} kg TNT (W^(1/3) = {} kg^(1/3)), coupling factor f = {}\n",
             significant(r.charge.mass), significant(w_cbrt), r.charge.coupling);
  for (const auto& law : r.laws) fmt::print("  n = {}: {}\n", law.attenuation, law.source);

  if (!r.ranges.empty()) {
    fmt::print("\nFree-field peaks\n");
    fmt::print("{:>6} {:>9} {:>14} {:>13} {:>15} {:>12} {:>12}\n", "n", "R [m]", "Z [m/kg^1/3]",
               "stress [MPa]", "velocity [m/s]", "accel. [g]", "displ. [mm]");
    for (const auto& law : r.laws) {
      for (double range : r.ranges) {
        const ShockPeaks p = free_field_peaks(law, r.charge, range);
        fmt::print("{:>6} {:>9} {:>14} {:>13} {:>15} {:>12} {:>12}\n", law.attenuation, significant(range),
                   significant(scaled_distance(range, r.charge.mass)), significant(p.stress / MPa),
                   significant(p.velocity), significant(p.acceleration / g),
                   significant(p.displacement / mm));
      }
    }
  }
  if (r.has_span) {
    fmt::print(
        "\nIn-structure shock: free-field peaks averaged over R = {} .. {} m (Z = {} .. {} m/kg^(1/3))\n",
        significant(r.span_near), significant(r.span_far),
        significant(scaled_distance(r.span_near, r.charge.mass)),
        significant(scaled_distance(r.span_far, r.charge.mass)));
    fmt::print("{:>6} {:>12} {:>12} {:>13} {:>12}\n", "n", "V_avg [m/s]", "a_avg [g]", "p_avg [MPa]",
               "d_avg [mm]");
    for (const auto& law : r.laws) {
      const ShockPeaks p = in_structure_shock(law, r.charge, r.span_near, r.span_far);
      fmt::print("{:>6} {:>12} {:>12} {:>13} {:>12}\n", law.attenuation, significant(p.velocity),
                 significant(p.acceleration / g), significant(p.stress / MPa),
                 significant(p.displacement / mm));
    }
  }
}

void print_csv(const EmpiricalRequest& r) {
  fmt::print(
      "section,attenuation_n,range_near_m,range_far_m,scaled_near_m_per_kg_cbrt,scaled_far_m_per_kg_cbrt,"
      "stress_MPa,velocity_m_per_s,acceleration_g,displacement_mm\n");
  const auto row = [&](const char* section, double n, double r1, double r2, const ShockPeaks& p) {
    fmt::print("{},{},{},{},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", section, n, r1, r2,
               scaled_distance(r1, r.charge.mass), scaled_distance(r2, r.charge.mass), p.stress / MPa,
               p.velocity, p.acceleration / g, p.displacement / mm);
  };
  for (const auto& law : r.laws)
    for (double range : r.ranges)
      row("free_field", law.attenuation, range, range, free_field_peaks(law, r.charge, range));
  if (r.has_span)
    for (const auto& law : r.laws)
      row("in_structure", law.attenuation, r.span_near, r.span_far,
          in_structure_shock(law, r.charge, r.span_near, r.span_far));
}

}  // namespace

void add_empirical_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<EmpiricalArguments>();
  auto* cmd = app.add_subcommand(
      "empirical", "TM 5-855-1 free-field ground shock and in-structure shock (Wang et al. 2005 §5.3, §5.5)");
  cmd->add_option("--charge-mass", args->charge_mass, "Charge mass W, kg of TNT (required)")->type_name("KG");
  cmd->add_option("--coupling", args->coupling, "Coupling factor f in (0, 1]; 1 = fully contained burst")
      ->type_name("F")
      ->capture_default_str();
  cmd->add_option("--attenuation", args->attenuation, "Attenuation coefficient(s) n (default: 2 and 2.5)")
      ->type_name("N");
  cmd->add_option("--range", args->ranges, "Range(s) R from the charge centre, m: prints free-field peaks")
      ->type_name("R");
  cmd->add_option("--span", args->span, "Near and far range R1 R2 of the structure, m: prints span averages")
      ->type_name("R1 R2");
  cmd->add_option("--law", args->law,
                  "Coefficients: 'wang2005' (the paper's printed numbers, n = 2 or 2.5) or 'tm5' "
                  "(manual's general equations with --soil-density and --seismic-velocity)")
      ->type_name("LAW")
      ->capture_default_str();
  cmd->add_option("--soil-density", args->soil_density, "Soil density, kg/m^3 (--law tm5; default 1920)")
      ->type_name("KG/M3");
  cmd->add_option("--seismic-velocity", args->seismic_velocity,
                  "Soil seismic (loading) velocity c, m/s (--law tm5; default 1400)")
      ->type_name("M/S");
  cmd->add_flag("--csv", args->csv, "Print CSV instead of a table");
  cmd->callback([args, &result] {
    try {
      const EmpiricalRequest request = check(*args);
      if (request.csv)
        print_csv(request);
      else
        print_table(request);
      result.exit_code = exit_ok;
    } catch (const OptionError& e) {
      std::cerr << "camouflet empirical: " << e.what() << "\n";
      result.exit_code = exit_bad_input;
    } catch (const InputError& e) {
      std::cerr << "camouflet empirical: " << e.what() << "\n";
      result.exit_code = exit_bad_input;
    }
  });
}

}  // namespace camouflet::app
