#include "output/summary_json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace camouflet {

namespace {
// JSON has no Inf or NaN: write null so that every reader still parses the file.
std::string number(double v) {
  return std::isfinite(v) ? fmt::format("{:.17g}", v) : "null";
}
}  // namespace

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
          out += fmt::format("\\u{:04x}", static_cast<int>(c));
        else
          out += c;
    }
  }
  return out + "\"";
}

Peak peak_of(const std::vector<double>& values, const std::vector<double>& time) {
  Peak p;
  double best = -1.0;
  for (std::size_t k = 0; k < values.size() && k < time.size(); ++k) {
    if (std::abs(values[k]) > best) {
      best = std::abs(values[k]);
      p = {values[k], time[k]};
    }
  }
  return p;
}

void GroupPeaks::add(std::size_t index, double value, double time) {
  if (index >= peaks.size()) {
    peaks.resize(index + 1);
    seen.resize(index + 1, false);
  }
  // A NaN sample never displaces a number, and any number displaces a NaN.
  if (!seen[index] || std::isnan(peaks[index].value) || std::abs(value) > std::abs(peaks[index].value)) {
    peaks[index] = {value, time};
    seen[index] = true;
  }
}

std::string summary_json(const Model& model, const RunSummary& s,
                         const std::vector<RunOutput::GaugeSeries>& gauges,
                         const std::vector<GroupPeaks>& peaks, const std::vector<std::size_t>& samples) {
  std::string b;
  auto out = std::back_inserter(b);
  const EnergyBalance& e = s.energy;
  fmt::format_to(out, "{{\n  \"case_file\": {},\n  \"title\": {},\n  \"geometry\": {},\n",
                 json_string(model.case_file), json_string(model.title),
                 json_string(to_string(model.run.mode)));
  fmt::format_to(
      out, "  \"final_time_s\": {},\n  \"end_time_s\": {},\n  \"cycles\": {},\n  \"wall_seconds\": {},\n",
      number(s.time), number(model.run.end_time), s.cycles, number(s.wall_seconds));
  fmt::format_to(out, "  \"stop_reason\": {},\n  \"failed\": {},\n", json_string(s.stop_reason),
                 s.failed ? "true" : "false");
  fmt::format_to(out, "  \"last_time_step\": {{\"dt_s\": {}, \"reason\": {}}},\n", number(s.last_limit.dt),
                 json_string(s.last_limit.reason));
  fmt::format_to(
      out,
      "  \"energy_J\": {{\n    \"kinetic\": {},\n    \"internal\": {},\n    \"hourglass\": {},\n"
      "    \"viscous\": {},\n    \"eroded\": {},\n    \"boundary_work\": {},\n    \"initial_total\": {},\n"
      "    \"relative_error\": {}\n  }},\n",
      number(e.kinetic), number(e.internal), number(e.hourglass), number(e.viscous), number(e.eroded),
      number(e.boundary_work), number(e.initial_total), number(e.relative_error));
  b += "  \"gauges\": {";
  for (std::size_t gi = 0; gi < gauges.size(); ++gi) {
    const auto& g = gauges[gi];
    fmt::format_to(out, "{}\n    {}: {{\n      \"csv\": {},\n      \"samples\": {},\n      \"peaks\": {{",
                   gi ? "," : "", json_string(g.group), json_string(g.group + ".csv"), samples[gi]);
    for (std::size_t p = 0; p < g.gauge_names.size(); ++p) {
      fmt::format_to(out, "{}\n        {}: {{", p ? "," : "", json_string(g.gauge_names[p]));
      for (std::size_t q = 0; q < g.quantities.size(); ++q) {
        const std::size_t k = q * g.gauge_names.size() + p;
        const Peak pk = k < peaks[gi].peaks.size() ? peaks[gi].peaks[k] : Peak{};
        fmt::format_to(out, "{}\n          {}: {{\"peak\": {}, \"time_s\": {}}}", q ? "," : "",
                       json_string(g.quantities[q]), number(pk.value), number(pk.time));
      }
      b += "\n        }";
    }
    b += "\n      }\n    }";
  }
  b += gauges.empty() ? "}\n}\n" : "\n  }\n}\n";
  return b;
}

}  // namespace camouflet
