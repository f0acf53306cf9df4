// [run] and [output]: run control and output intervals (docs/case-format.md).
#include <fmt/format.h>

#include "case/sections.hpp"

namespace camouflet::case_detail {

ViscosityForm read_viscosity_form(TomlReader& v, ViscosityForm fallback) {
  if (!v.has("form")) return fallback;
  const std::string form = v.choice("form", {"acceleration", "volumetric", "edge"}, "acceleration");
  return form == "edge" ? ViscosityForm::edge : form == "volumetric" ? ViscosityForm::volumetric : ViscosityForm::acceleration;
}

void read_run(TomlReader& r, Model& model) {
  RunControl& run = model.run;
  run.where = r.where();
  const std::string geometry = r.choice("geometry", {"plane_strain", "axisymmetric", "3d"}, "plane_strain");
  run.mode = geometry == "3d"             ? GeometryMode::three_d
             : geometry == "axisymmetric" ? GeometryMode::axisymmetric
                                          : GeometryMode::plane_strain;
  run.end_time = r.positive("end_time");
  run.cfl = r.number("cfl", run.cfl);
  // Central differences are stable for dt below the critical step: a factor above 1 is never safe.
  if (!(run.cfl > 0.0 && run.cfl <= 1.0)) r.fail("cfl", fmt::format("must lie in (0, 1], got {}", run.cfl));
  run.initial_dt = r.non_negative("initial_dt", run.initial_dt);
  run.min_dt = r.non_negative("min_dt", run.min_dt);
  if (r.has("max_dt")) run.max_dt = r.positive("max_dt");
  if (run.min_dt >= run.max_dt) r.fail("min_dt", fmt::format("must be below max_dt = {} s", run.max_dt));
  if (run.initial_dt > run.max_dt)
    r.fail("initial_dt", fmt::format("must not exceed max_dt = {} s", run.max_dt));
  if (r.has("max_cycles")) {
    run.max_cycles = r.integer("max_cycles", run.max_cycles);
    if (run.max_cycles < 1) r.fail("max_cycles", "must be at least 1");
  }
  run.dt_growth = r.number("dt_growth", run.dt_growth);
  if (!(run.dt_growth >= 1.0)) r.fail("dt_growth", fmt::format("must be at least 1, got {}", run.dt_growth));
  if (r.has("energy_error_limit")) run.energy_error_limit = r.positive("energy_error_limit");
  if (r.has("axisymmetric_momentum")) {
    run.area_weighted_momentum = r.choice("axisymmetric_momentum", {"volume", "area"}, "volume") == "area";
    if (run.area_weighted_momentum && run.mode != GeometryMode::axisymmetric)
      r.fail("axisymmetric_momentum", "\"area\" needs geometry mode 'axisymmetric'");
  }
  // Domain box: a node or particle leaving it stops the run.
  const int dim = dimension_of(run.mode);
  if (r.has("domain_min")) run.domain_min = r.vector("domain_min", dim);
  if (r.has("domain_max")) run.domain_max = r.vector("domain_max", dim);
  for (int i = 0; i < dim; ++i)
    if (!(run.domain_min[static_cast<std::size_t>(i)] < run.domain_max[static_cast<std::size_t>(i)]))
      r.fail("domain_max", fmt::format("component {} must exceed domain_min's", i + 1));

  if (r.has("gravity")) {
    run.gravity = r.vector("gravity", dim);
    // On the axis of revolution a radial body force has no meaning: it would pull the rings apart.
    if (run.mode == GeometryMode::axisymmetric && run.gravity[0] != 0.0)
      r.fail("gravity", fmt::format("an r-z model takes gravity along z only; got a radial component {} m/s^2",
                                    run.gravity[0]));
  }

  if (auto d = r.table("dynamic_relaxation")) {
    RunControl::DynamicRelaxation dr;
    dr.where = d->where();
    dr.period = d->positive("period");
    dr.tolerance = d->positive("tolerance", dr.tolerance);
    if (dr.tolerance >= 1.0) d->fail("tolerance", fmt::format("must lie below 1, got {}", dr.tolerance));
    // Twenty periods: a damping at the critical rate settles the fundamental mode in about one.
    dr.max_time = d->positive("max_time", 20.0 * dr.period);
    if (dr.max_time < 2.0 * dr.period)
      d->fail("max_time",
              fmt::format("must allow at least two periods ({} s), got {} s", 2.0 * dr.period, dr.max_time));
    d->finish();
    run.relaxation = dr;
  }

  if (auto v = r.table("viscosity")) {
    run.viscosity_linear = v->non_negative("linear", run.viscosity_linear);
    run.viscosity_quadratic = v->non_negative("quadratic", run.viscosity_quadratic);
    run.viscosity_form = read_viscosity_form(*v, run.viscosity_form);
    run.viscosity_limiter =
        v->choice("limiter", {"none", "csw"}, run.viscosity_limiter ? "csw" : "none") == "csw";
    v->finish();
  }
  if (auto h = r.table("hourglass")) {
    const std::string form = h->choice("form", {"viscous", "stiffness", "none"}, "viscous");
    run.hourglass = form == "stiffness" ? HourglassForm::stiffness
                    : form == "none"    ? HourglassForm::none
                                        : HourglassForm::viscous;
    run.hourglass_coefficient = h->non_negative("coefficient", run.hourglass_coefficient);
    run.subzonal_pressure = h->non_negative("subzonal", run.subzonal_pressure);
    if (run.hourglass_coefficient > 0.5)
      h->fail("coefficient", fmt::format("must not exceed 0.5, got {}", run.hourglass_coefficient));
    h->finish();
  }
  r.finish();
}

void read_output(TomlReader& r, Model& model) {
  OutputControl& out = model.output;
  out.field_interval = r.non_negative("field_interval", out.field_interval);
  out.gauge_interval = r.non_negative("gauge_interval", out.gauge_interval);
  out.log_interval_s = r.non_negative("log_interval", out.log_interval_s);
  if (out.field_interval > 0.0 && model.run.end_time / out.field_interval > 1e5)
    r.fail("field_interval",
           fmt::format("asks for {:.0f} snapshots; at most 100000", model.run.end_time / out.field_interval));
  r.finish();
}

}  // namespace camouflet::case_detail
