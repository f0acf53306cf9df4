#!/usr/bin/env python3
"""In-structure shock from gauge histories, the way protective-design engineers
read it: a zero-phase low-pass filter with a stated cut-off, and shock
response spectra (SRS) of a base motion. Used by the report; tested against
analytic answers in tests/app/test_structure_shock.cpp.

Filter. A Butterworth low-pass of order 2 run forwards and backwards
(scipy.signal.sosfiltfilt): no phase shift, the gain of the pass squared, so
an effective order of 4, as in the phaseless channel-frequency-class filters
of SAE J211 / ISO 6487. The design frequency is set so that the *combined*
gain at the stated cut-off f_c is -3.01 dB (1/sqrt 2): the order-2 gain
squared is 1 / (1 + (f/f_d)^4), so f_d = f_c / (sqrt 2 - 1)^(1/4) = 1.2465 f_c
well below the sampling rate f_s; the digital filter (bilinear transform)
reaches it exactly with tan(pi f_d / f_s) = tan(pi f_c / f_s) / (sqrt 2 - 1)^(1/4).
(J211's CFC n has its -3 dB point at about 5/3 n Hz: CFC 600 is f_c = 1000 Hz.)

SRS. For each natural frequency f_n and damping ratio zeta, the single-degree-
of-freedom system z'' + 2 zeta w z' + w^2 z = -a_base(t), w = 2 pi f_n, is
solved exactly for a base acceleration linear between samples
(scipy.signal.lsim, first-order hold), over the record and a zero-padded tail
long enough for the residual response (maximax spectrum). Reported: the
pseudo-velocity w max|z|, the absolute acceleration max|z'' + a_base|
= max|2 zeta w z' + w^2 z| and the relative displacement max|z|.
"""
import math

import numpy as np
from scipy import signal

# In-structure accelerations and the interface stress are low-passed at this cut-off by the report
# and the run metrics (zero-phase, -3 dB here; about SAE J211's CFC 600).
CUTOFF_HZ = 1000.0


def lowpass_design_frequency(cutoff_hz, sampling_hz):
    """Design frequency of the digital order-2 Butterworth whose forward-backward
    pass has its -3.01 dB point at cutoff_hz."""
    if not 0.0 < cutoff_hz < 0.5 * sampling_hz:
        raise ValueError(f"lowpass: cut-off {cutoff_hz} Hz must lie between 0 and half the "
                         f"sampling rate, {0.5 * sampling_hz:.6g} Hz")
    warped = math.tan(math.pi * cutoff_hz / sampling_hz) / (math.sqrt(2.0) - 1.0) ** 0.25
    return sampling_hz / math.pi * math.atan(warped)


def lowpass(t, x, cutoff_hz):
    """x(t), uniformly sampled, filtered by the zero-phase filter above."""
    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(t) < 2:
        raise ValueError("lowpass: need at least two samples")
    dt = (t[-1] - t[0]) / (len(t) - 1)
    if not np.allclose(np.diff(t), dt, rtol=1e-6, atol=0.0):
        raise ValueError("lowpass: the samples must be evenly spaced")
    fs = 1.0 / dt
    fd = lowpass_design_frequency(cutoff_hz, fs)
    sos = signal.butter(2, fd, btype="low", fs=fs, output="sos")
    return signal.sosfiltfilt(sos, x)


def uniform(t, x):
    """(t, x) on an evenly spaced grid of the same number of samples (gauge rows
    are written at the first cycle past each interval, not exactly on it)."""
    tu = np.linspace(t[0], t[-1], len(t))
    return tu, np.interp(tu, t, x)


def can_lowpass(tu, cutoff_hz=CUTOFF_HZ):
    """Whether an even grid tu is long and fine enough to low-pass at cutoff_hz."""
    return len(tu) >= 16 and cutoff_hz < 0.5 * (len(tu) - 1) / (tu[-1] - tu[0])


def filtered_acceleration(t, v, cutoff_hz=CUTOFF_HZ):
    """Acceleration low-passed at cutoff_hz, on an even grid, from the velocity
    gauge v(t); None if sampled too coarsely. The acceleration gauge is the
    nodal acceleration of one cycle every few dozen, which aliases the
    cycle-to-cycle noise: on the coarse case its integral drifts by 2-3 m/s from
    the velocity. The velocity's difference quotient is the mean acceleration
    over each interval and integrates back to the velocity."""
    tu, vu = uniform(t, v)
    if not can_lowpass(tu, cutoff_hz):
        return None
    return tu, lowpass(tu, np.gradient(vu, tu), cutoff_hz)


def filtered(t, x, cutoff_hz=CUTOFF_HZ):
    """x(t) low-passed at cutoff_hz on an even grid, or None if sampled too coarsely."""
    tu, xu = uniform(t, x)
    if not can_lowpass(tu, cutoff_hz):
        return None
    return tu, lowpass(tu, xu, cutoff_hz)


def shock_response_spectrum(t, base_acceleration, frequencies_hz, damping=0.05, tail_periods=2.0):
    """Maximax SRS of a base acceleration (m/s^2) sampled at t (s).

    Returns a dict of arrays over frequencies_hz: 'pseudo_velocity' (m/s),
    'acceleration' (m/s^2, absolute) and 'displacement' (m, relative)."""
    t = np.asarray(t, dtype=float)
    a = np.asarray(base_acceleration, dtype=float)
    dt = (t[-1] - t[0]) / (len(t) - 1)
    f = np.asarray(frequencies_hz, dtype=float)
    if np.any(f <= 0.0):
        raise ValueError("shock_response_spectrum: frequencies must be positive")
    # The residual response of the lowest frequency needs its tail.
    n_tail = int(math.ceil(tail_periods / (f.min() * dt)))
    tt = t[0] + dt * np.arange(len(t) + n_tail)
    aa = np.concatenate([a, np.zeros(n_tail)])
    pv, acc, disp = [], [], []
    for fn in f:
        w = 2.0 * math.pi * fn
        # State (z, z'): z'' = -w^2 z - 2 zeta w z' - a_base.
        system = signal.StateSpace([[0.0, 1.0], [-w * w, -2.0 * damping * w]], [[0.0], [-1.0]],
                                   [[1.0, 0.0], [w * w, 2.0 * damping * w]], [[0.0], [0.0]])
        _, y, _ = signal.lsim(system, aa, tt, interp=True)
        z, absolute = y[:, 0], y[:, 1]
        disp.append(np.max(np.abs(z)))
        pv.append(w * disp[-1])
        acc.append(np.max(np.abs(absolute)))
    return {"pseudo_velocity": np.array(pv), "acceleration": np.array(acc), "displacement": np.array(disp)}
