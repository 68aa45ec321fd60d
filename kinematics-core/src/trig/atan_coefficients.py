#!/usr/bin/env python3
"""Derive the constants of kinematics-core's atan2 and print them as Rust.

Run from the repository root:

    python3 kinematics-core/src/trig/atan_coefficients.py > kinematics-core/src/trig/atan_coefficients.rs

(needs mpmath from PyPI; checked with mpmath 1.3.0). Everything in atan_coefficients.rs is this
script's output, unedited. It reuses the Remez fit of coefficients.py beside it.

What it derives:

* A minimax polynomial on [0, T^2], T = tan(pi/8) * (1 + 1e-6) (the reduced argument is a
  quotient rounded in f64, so it can land a hair past tan(pi/8)), for
      atan(u) = u + u^3 * A(u^2),   A(z) ~ (atan(sqrt z) - sqrt z) / z^1.5
  minimising the error relative to atan(u), its coefficients rounded to f64 one at a time, the
  higher ones refitted after each rounding.
* pi/4, pi/2 and pi as a sum hi + lo of two f64 (hi the nearest f64, lo the rest rounded), so the
  octant's base angle adds without its own rounding error.
"""

import os
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from coefficients import fit_rounded, rust_f64  # noqa: E402

mp.mp.dps = 50

T = mp.tan(mp.pi / 8) * (1 + mp.mpf("1e-6"))
ZMAX = T * T
ZLOW = ZMAX * mp.mpf("1e-4")
COUNT = 11


def atan_tail(z):
    """(atan(sqrt z) - sqrt z) / z^1.5 from its series (no 0/0 at z = 0)."""
    total, k = mp.mpf(0), 1
    while True:
        t = (-1) ** k * z ** (k - 1) / (2 * k + 1)
        total += t
        if abs(t) < mp.mpf(10) ** (-mp.mp.dps) and k > 3:
            return total
        k += 1


def atan_weight(z):
    """An error e in A(z) is an error z * e * u / atan(u) relative to atan(u)."""
    u = mp.sqrt(z)
    return z * u / mp.atan(u)


def hi_lo(value):
    hi = mp.mpf(float(value))
    return hi, mp.mpf(float(value - hi))


def main():
    coeffs, level = fit_rounded(atan_tail, atan_weight, ZLOW, ZMAX, COUNT)
    from coefficients import max_error  # noqa: E402

    rounded = max_error(atan_tail, atan_weight, coeffs, ZLOW, ZMAX)
    print("//! Constants of the atan2 kernel: the OUTPUT of `atan_coefficients.py` beside this file, unedited.")
    print("//!")
    print("//! Regenerate with `python3 kinematics-core/src/trig/atan_coefficients.py >")
    print("//! kinematics-core/src/trig/atan_coefficients.rs` (mpmath 1.3.0); see that script for the derivation.")
    print()
    print(f"/// tan(pi/8) rounded to f64: the bound of the reduced argument.")
    print(f"pub const TAN_PI_8: f64 = {rust_f64(mp.tan(mp.pi / 8))};")
    for name, value in [("FRAC_PI_4", mp.pi / 4), ("FRAC_PI_2", mp.pi / 2), ("PI", mp.pi)]:
        hi, lo = hi_lo(value)
        print(f"/// {name.replace('FRAC_', '').replace('_', '/').lower()} as hi + lo: the nearest f64, then the rest.")
        print(f"pub const {name}_LO: f64 = {rust_f64(lo)};")
    print()
    print(
        f"/// Minimax coefficients of atan(u) = u + u^3 * A(u^2), lowest power first, on |u| <= tan(pi/8) (1 + 1e-6),\n"
        f"/// error relative to atan(u). Error of the unrounded fit: {mp.nstr(level, 3)};\n"
        f"/// with the coefficients rounded to f64 (one at a time, the rest refitted): {mp.nstr(rounded, 3)}."
    )
    print(f"pub const ATAN_F64: [f64; {COUNT}] = [")
    for c in coeffs:
        print(f"    {rust_f64(c)},")
    print("];")


if __name__ == "__main__":
    main()
