#!/usr/bin/env python3
"""Analytic cases for scripts/structure_shock.py, printed as
'<name> <expected> <computed>' lines that tests/app/test_structure_shock.cpp
checks and records in the verification report."""
import math
import pathlib
import sys

import numpy as np
from scipy import integrate

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import structure_shock as ss  # noqa: E402


def gain_db(f, cutoff, fs=20000.0, duration=0.2):
    t = np.arange(int(duration * fs)) / fs
    y = ss.lowpass(t, np.sin(2 * math.pi * f * t), cutoff)
    mid = slice(len(t) // 4, 3 * len(t) // 4)  # clear of the end transients
    return 20 * math.log10(np.max(np.abs(y[mid])))


def filter_cases():
    fc = 1000.0
    print("filter_gain_at_cutoff_db", -10 * math.log10(2), gain_db(fc, fc))
    print("filter_gain_at_tenth_cutoff_db", 10 * math.log10(1 / (1 + (0.1 / 1.2465) ** 4)), gain_db(0.1 * fc, fc))
    # Zero phase: a Gaussian pulse keeps its peak time.
    fs = 20000.0
    t = np.arange(4000) / fs
    x = np.exp(-((t - 0.1) / 0.002) ** 2)
    y = ss.lowpass(t, x, fc)
    print("filter_peak_shift_s", 0.0, t[np.argmax(y)] - 0.1)


def half_sine_closed_form(A, tau, fn):
    """Undamped maximax absolute-acceleration SRS of the base pulse A sin(pi t/tau)."""
    w, W = 2 * math.pi * fn, math.pi / tau
    t = np.linspace(0.0, tau, 200001)
    k = -A / (w * w - W * W)
    z = k * (np.sin(W * t) - (W / w) * np.sin(w * t))
    z_tau = k * (math.sin(W * tau) - (W / w) * math.sin(w * tau))
    v_tau = k * (W * math.cos(W * tau) - W * math.cos(w * tau))
    residual = math.hypot(z_tau, v_tau / w)
    return w * w * max(np.max(np.abs(z)), residual)


def half_sine_cases():
    A, tau, dt = 1000.0, 1e-3, 5e-6
    t = np.arange(0.0, 0.02, dt)
    a = np.where(t <= tau, A * np.sin(math.pi * np.minimum(t, tau) / tau), 0.0)
    freqs = [37.0, 113.0, 317.0, 731.0, 1290.0, 3170.0]
    srs = ss.shock_response_spectrum(t, a, freqs, damping=0.0)
    for fn, sa in zip(freqs, srs["acceleration"]):
        print(f"half_sine_srs_{fn:g}Hz", half_sine_closed_form(A, tau, fn), sa)


def direct_cases():
    dt = 2e-5
    t = np.arange(0.0, 0.05, dt)
    rng = np.random.default_rng(7)
    a = 500.0 * np.exp(-t / 0.01) * np.sin(2 * math.pi * 400 * t + 3 * np.sin(2 * math.pi * 90 * t)) \
        + 50.0 * rng.standard_normal(len(t)) * np.exp(-t / 0.005)
    zeta = 0.05
    freqs = [60.0, 250.0, 900.0]
    srs = ss.shock_response_spectrum(t, a, freqs, damping=zeta)
    tail = 2.0 / min(freqs)
    for fn, pv in zip(freqs, srs["pseudo_velocity"]):
        w = 2 * math.pi * fn

        def rhs(s, y):
            base = np.interp(s, t, a, right=0.0)
            return [y[1], -w * w * y[0] - 2 * zeta * w * y[1] - base]

        span = (0.0, t[-1] + tail)
        times = np.arange(0.0, span[1], dt)
        sol = integrate.solve_ivp(rhs, span, [0.0, 0.0], t_eval=times, rtol=1e-10, atol=1e-14, max_step=dt / 2)
        print(f"direct_pv_{fn:g}Hz", w * np.max(np.abs(sol.y[0])), pv)


if __name__ == "__main__":
    filter_cases()
    half_sine_cases()
    direct_cases()
