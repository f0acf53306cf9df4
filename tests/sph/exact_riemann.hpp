#pragma once
// Exact solution of the Riemann problem for an ideal gas (Toro, "Riemann
// Solvers and Numerical Methods for Fluid Dynamics", 3rd ed., chapter 4):
// the star pressure from f_L(p) + f_R(p) + u_R - u_L = 0 (eq. 4.5) by Newton
// iteration, then the solution sampled at x/t (section 4.5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace camouflet::test {

struct GasState {
  double density = 0.0;   // kg/m^3
  double velocity = 0.0;  // m/s
  double pressure = 0.0;  // Pa
};

class ExactRiemann {
 public:
  ExactRiemann(GasState left, GasState right, double gamma) : l_(left), r_(right), g_(gamma) {
    cl_ = std::sqrt(g_ * l_.pressure / l_.density);
    cr_ = std::sqrt(g_ * r_.pressure / r_.density);
    double p = 0.5 * (l_.pressure + r_.pressure);  // initial guess (Toro eq. 4.47)
    for (int it = 0; it < 100; ++it) {
      double fl, dfl, fr, dfr;
      wave(p, l_, cl_, fl, dfl);
      wave(p, r_, cr_, fr, dfr);
      const double f = fl + fr + r_.velocity - l_.velocity;
      const double p_new = std::max(1e-12 * p, p - f / (dfl + dfr));
      if (std::abs(p_new - p) <= 1e-14 * (p_new + p)) {
        p = p_new;
        break;
      }
      p = p_new;
    }
    p_star_ = p;
    double fl, dfl, fr, dfr;
    wave(p, l_, cl_, fl, dfl);
    wave(p, r_, cr_, fr, dfr);
    u_star_ = 0.5 * (l_.velocity + r_.velocity) + 0.5 * (fr - fl);
  }

  double star_pressure() const { return p_star_; }
  double star_velocity() const { return u_star_; }
  // Head speed of the shock (right) when p* > p_R (Toro eq. 4.59).
  double right_shock_speed() const {
    return r_.velocity + cr_ * std::sqrt((g_ + 1) / (2 * g_) * p_star_ / r_.pressure + (g_ - 1) / (2 * g_));
  }
  // Tail of the left rarefaction, u* - c*_L (Toro eq. 4.55).
  double left_rarefaction_tail() const {
    return u_star_ - cl_ * std::pow(p_star_ / l_.pressure, (g_ - 1) / (2 * g_));
  }
  double left_rarefaction_head() const { return l_.velocity - cl_; }

  // State at similarity coordinate s = x / t (interface at x = 0).
  GasState sample(double s) const {
    const double g = g_;
    if (s <= u_star_) {
      if (p_star_ > l_.pressure) {  // left shock
        const double sl =
            l_.velocity - cl_ * std::sqrt((g + 1) / (2 * g) * p_star_ / l_.pressure + (g - 1) / (2 * g));
        if (s <= sl) return l_;
        const double ratio = p_star_ / l_.pressure, k = (g - 1) / (g + 1);
        return {l_.density * (ratio + k) / (k * ratio + 1), u_star_, p_star_};
      }
      const double head = l_.velocity - cl_;
      const double tail = left_rarefaction_tail();
      if (s <= head) return l_;
      if (s >= tail) return {l_.density * std::pow(p_star_ / l_.pressure, 1 / g), u_star_, p_star_};
      const double c = 2 / (g + 1) * (cl_ + (g - 1) / 2 * (l_.velocity - s));
      const double u = 2 / (g + 1) * (cl_ + (g - 1) / 2 * l_.velocity + s);
      const double rho = l_.density * std::pow(c / cl_, 2 / (g - 1));
      return {rho, u, l_.pressure * std::pow(c / cl_, 2 * g / (g - 1))};
    }
    if (p_star_ > r_.pressure) {  // right shock
      if (s >= right_shock_speed()) return r_;
      const double ratio = p_star_ / r_.pressure, k = (g - 1) / (g + 1);
      return {r_.density * (ratio + k) / (k * ratio + 1), u_star_, p_star_};
    }
    const double head = r_.velocity + cr_;
    const double tail = u_star_ + cr_ * std::pow(p_star_ / r_.pressure, (g - 1) / (2 * g));
    if (s >= head) return r_;
    if (s <= tail) return {r_.density * std::pow(p_star_ / r_.pressure, 1 / g), u_star_, p_star_};
    const double c = 2 / (g + 1) * (cr_ - (g - 1) / 2 * (r_.velocity - s));
    const double u = 2 / (g + 1) * (-cr_ + (g - 1) / 2 * r_.velocity + s);
    const double rho = r_.density * std::pow(c / cr_, 2 / (g - 1));
    return {rho, u, r_.pressure * std::pow(c / cr_, 2 * g / (g - 1))};
  }

 private:
  // Toro eqs. 4.6-4.7 and their derivatives (4.37).
  void wave(double p, const GasState& k, double c, double& f, double& df) const {
    const double g = g_;
    if (p > k.pressure) {
      const double a = 2 / ((g + 1) * k.density), b = (g - 1) / (g + 1) * k.pressure;
      const double q = std::sqrt(a / (p + b));
      f = (p - k.pressure) * q;
      df = q * (1 - 0.5 * (p - k.pressure) / (b + p));
    } else {
      const double ratio = p / k.pressure;
      f = 2 * c / (g - 1) * (std::pow(ratio, (g - 1) / (2 * g)) - 1);
      df = 1 / (k.density * c) * std::pow(ratio, -(g + 1) / (2 * g));
    }
  }

  GasState l_, r_;
  double g_;
  double cl_ = 0, cr_ = 0, p_star_ = 0, u_star_ = 0;
};

}  // namespace camouflet::test
