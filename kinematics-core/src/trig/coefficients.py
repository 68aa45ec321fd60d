#!/usr/bin/env python3
"""Derive the constants of kinematics-core's sin/cos and print them as Rust.

Run from the repository root:

    python3 kinematics-core/src/trig/coefficients.py > kinematics-core/src/trig/coefficients.rs

(needs mpmath from PyPI; checked with mpmath 1.3.0). Everything in coefficients.rs is this script's
output, unedited.

What it derives:

* The Cody-Waite split of pi/2 into PIO2_1..PIO2_4. The first three keep 33 significant bits, so
  `k * PIO2_n` is exact for every integer |k| < 2^20 (33 + 20 = 53 bits); the fast path's bound
  |x| <= 2^20 gives |k| <= 2^20 * 2/pi + 1 < 2^20. PIO2_4 is the remainder rounded to 53 bits: its
  product's rounding error is about 2^-53 * 2^20 * 2^-100, far below anything that matters.
* Minimax (Remez) polynomials on [0, R^2], R = pi/4 * (1 + 1e-6) (a margin because k is rounded
  from the product x * (2/pi) in f64, which can put r a hair past pi/4), for
      sin(r) = r + r^3 * S(r^2),          S(z) ~ (sin(sqrt z) - sqrt z) / z^1.5
      cos(r) = 1 - r^2/2 + r^4 * C(r^2),   C(z) ~ (cos(sqrt z) - 1 + z/2) / z^2
  with 6 coefficients each for f64, each minimising the error relative to sin(r) or cos(r). The
  coefficients are rounded to f64 one at a time, the higher ones refitted after each rounding. The
  script prints each fit's levelled relative error and the error after rounding (the doc comments
  in coefficients.rs).
* The f32 routines' own constants (they compute in f32): 2/pi rounded to f32; pi/2 split in two
  16-bit parts, each rounded down (so the parts and the rest are positive, which keeps the sign of
  a zero through the reduction), and the rest rounded to f32, so `k * part` is exact for every
  integer |k| < 2^8 (the f32 fast path's bound |x| <= 256 gives |k| <= 163); and the same two
  kernels with 3 coefficients each, fitted on [0, R32^2], R32 = pi/4 * (1 + 1e-4) (k is rounded from
  the f32 product x * (2/pi), up to about 1.3e-5 of a quadrant off at |x| = 256), the
  coefficients rounded to f32 one at a time.
"""

import struct

import mpmath as mp

mp.mp.dps = 50

R = mp.pi / 4 * (1 + mp.mpf("1e-6"))
ZMAX = R * R
# The weights below vanish at z = 0, so the fits start just above it; below ZLOW the weighted
# error only shrinks (it is z times a bounded function).
ZLOW = ZMAX * mp.mpf("1e-4")


def sin_weight(z):
    """An error e in S(z) is an error z * e * r / sin(r) relative to sin(r)."""
    r = mp.sqrt(z)
    return z * r / mp.sin(r)


def cos_weight(z):
    """An error e in C(z) is an error z^2 * e / cos(r) relative to cos(r)."""
    return z * z / mp.cos(mp.sqrt(z))


def sin_tail(z):
    """(sin(sqrt z) - sqrt z) / z^1.5 from its Taylor series (no 0/0 at z = 0)."""
    total, term, k = mp.mpf(0), mp.mpf(1), 1
    while True:
        t = (-1) ** k * z ** (k - 1) / mp.factorial(2 * k + 1)
        total += t
        if abs(t) < mp.mpf(10) ** (-mp.mp.dps) and k > 3:
            return total
        k += 1


def cos_tail(z):
    """(cos(sqrt z) - 1 + z/2) / z^2 from its Taylor series."""
    total, k = mp.mpf(0), 2
    while True:
        t = (-1) ** k * z ** (k - 2) / mp.factorial(2 * k)
        total += t
        if abs(t) < mp.mpf(10) ** (-mp.mp.dps) and k > 4:
            return total
        k += 1


def horner(coeffs, z):
    acc = mp.mpf(0)
    for c in reversed(coeffs):
        acc = acc * z + c
    return acc


def remez(f, w, a, b, n, iterations=40, grid=2000):
    """Minimax polynomial of degree n-1 (n coefficients) for f on [a, b], minimising max |w (p - f)|.

    Classic exchange: solve p(x_i) + (-1)^i E / w(x_i) = f(x_i) on n+1 reference points, then move
    the reference to the alternating extrema of the weighted error found on a dense grid.
    """
    m = n + 1
    ref = [(a + b) / 2 - (b - a) / 2 * mp.cos(mp.pi * i / (m - 1)) for i in range(m)]
    xs = [a + (b - a) * mp.mpf(i) / grid for i in range(grid + 1)]
    fx = [f(x) for x in xs]
    coeffs, level = None, None
    for _ in range(iterations):
        mat = mp.matrix(m, m)
        rhs = mp.matrix(m, 1)
        for i, x in enumerate(ref):
            for j in range(n):
                mat[i, j] = x**j
            mat[i, n] = (-1) ** i / w(x)
            rhs[i] = f(x)
        sol = mp.lu_solve(mat, rhs)
        coeffs = [sol[j] for j in range(n)]
        level = abs(sol[n])
        err = [(horner(coeffs, x) - y) * w(x) for x, y in zip(xs, fx)]
        # Local extrema of the error (endpoints included), then one per run of equal sign.
        ext = [
            i
            for i in range(len(xs))
            if (i == 0 or abs(err[i]) >= abs(err[i - 1]))
            and (i == len(xs) - 1 or abs(err[i]) >= abs(err[i + 1]))
        ]
        runs = []
        for i in ext:
            if runs and mp.sign(err[runs[-1]]) == mp.sign(err[i]):
                if abs(err[i]) > abs(err[runs[-1]]):
                    runs[-1] = i
            else:
                runs.append(i)
        while len(runs) > m:  # drop the smaller end
            if abs(err[runs[0]]) < abs(err[runs[-1]]):
                runs.pop(0)
            else:
                runs.pop()
        if len(runs) < m:
            break
        ref = [xs[i] for i in runs]
        top = max(abs(e) for e in err)
        if top - level < level * mp.mpf("1e-6"):
            break
    return coeffs, level


def max_error(f, w, coeffs, a, b, grid=5000):
    xs = [a + (b - a) * mp.mpf(i) / grid for i in range(grid + 1)]
    return max(abs((horner(coeffs, x) - f(x)) * w(x)) for x in xs)


def to_f64(v):
    return mp.mpf(float(v))


def to_f32(v):
    return mp.mpf(struct.unpack("<f", struct.pack("<f", float(v)))[0])


def fit_rounded(f, w, a, b, n, rounding=to_f64):
    """Remez fit whose coefficients are rounded (to f64, or by `rounding`) one at a time, lowest
    first, each later coefficient refitted with the earlier ones fixed (so rounding the big ones
    costs little)."""
    fixed = []
    first_level = None
    for j in range(n):
        def rest(z, j=j):
            return (f(z) - horner(fixed, z)) / z**j

        def weight(z, j=j):
            return w(z) * z**j

        coeffs, _ = remez(rest, weight, a, b, n - j)
        if first_level is None:
            first_level = max_error(f, w, coeffs, a, b)
        fixed.append(rounding(coeffs[0]))
    return fixed, first_level


def split(value, bits, rounding=mp.nint):
    """value rounded to `bits` significant bits (as an exact mpf), to nearest unless `rounding` is
    another of mpmath's (mp.floor: down)."""
    e = mp.floor(mp.log(abs(value), 2))
    scale = mp.mpf(2) ** (bits - 1 - e)
    return rounding(value * scale) / scale


def rust_f64(v):
    f = float(v)
    s = repr(f)
    if "e" not in s and "." not in s:
        s += ".0"
    return s


def main():
    print("//! Constants of the sin/cos kernels: the OUTPUT of `coefficients.py` beside this file, unedited.")
    print("//!")
    print("//! Regenerate with `python3 kinematics-core/src/trig/coefficients.py >")
    print("//! kinematics-core/src/trig/coefficients.rs` (mpmath 1.3.0); see that script for the derivation.")
    print()
    half_pi = mp.pi / 2
    p1 = split(half_pi, 33)
    p2 = split(half_pi - p1, 33)
    p3 = split(half_pi - p1 - p2, 33)
    p4 = mp.mpf(float(half_pi - p1 - p2 - p3))
    for p in (p1, p2, p3):
        assert mp.mpf(float(p)) == p
    tail = half_pi - p1 - p2 - p3 - p4
    two_over_pi = float(2 / mp.pi)
    bits = struct.unpack("<Q", struct.pack("<d", two_over_pi))[0]
    print(f"/// 2/pi rounded to f64 ({rust_f64(two_over_pi)}, bits {bits:#018x}: core's constant, which")
    print("/// clippy wants by name); `x * FRAC_2_PI` picks the quadrant count k.")
    print("pub const FRAC_2_PI: f64 = core::f64::consts::FRAC_2_PI;")
    print(f"/// The bits of 2/pi rounded to f64, as computed here; a unit test holds core's constant to it.")
    print(f"#[cfg(test)]")
    print(f"pub const FRAC_2_PI_BITS: u64 = {bits:#018x};")
    print("/// pi/2 to 33 significant bits: `k * PIO2_1` is exact for |k| < 2^20.")
    print(f"pub const PIO2_1: f64 = {rust_f64(p1)};")
    print("/// The next 33 bits of pi/2.")
    print(f"pub const PIO2_2: f64 = {rust_f64(p2)};")
    print("/// The next 33 bits of pi/2.")
    print(f"pub const PIO2_3: f64 = {rust_f64(p3)};")
    print(f"/// The rest of pi/2 rounded to f64; pi/2 - (PIO2_1 + .. + PIO2_4) = {mp.nstr(tail, 3)}.")
    print(f"pub const PIO2_4: f64 = {rust_f64(p4)};")
    sin_w = "error relative to sin(r)"
    cos_w = "error relative to cos(r)"
    for name, f, w, weighting, n, what in (
        ("SIN_F64", sin_tail, sin_weight, sin_w, 6, "sin(r) = r + r^3 * S(r^2), f64 kernel"),
        ("COS_F64", cos_tail, cos_weight, cos_w, 6, "cos(r) = 1 - r^2/2 + r^4 * C(r^2), f64 kernel"),
    ):
        print()
        rounded, level = fit_rounded(f, w, ZLOW, ZMAX, n)
        after = max_error(f, w, rounded, ZLOW, ZMAX)
        print(f"/// Minimax coefficients of {what}, lowest power first, on r in [0, pi/4 (1 + 1e-6)],")
        print(f"/// {weighting}. Error of the unrounded fit: {mp.nstr(level, 3)};")
        print(f"/// with the coefficients rounded to f64 (one at a time, the rest refitted): {mp.nstr(after, 3)}.")
        print(f"pub const {name}: [f64; {n}] = [")
        for c in rounded:
            print(f"    {rust_f64(c)},")
        print("];")
    print_f32(half_pi, sin_w, cos_w)


def rust_f32(v):
    """The shortest decimal that reads back as the f32 `v` (an exact f32 value)."""
    for digits in range(1, 12):
        text = f"{float(v):.{digits}e}"
        if to_f32(float(text)) == v:
            mantissa, exponent = text.split("e")
            mantissa = mantissa.rstrip("0").rstrip(".") if "." in mantissa else mantissa
            if "." not in mantissa:
                mantissa += ".0"
            exponent = int(exponent)
            return mantissa if exponent == 0 else f"{mantissa}e{exponent}"
    raise AssertionError(v)


def print_f32(half_pi, sin_w, cos_w):
    """The f32 routines' constants: they compute in f32 (see the docstring)."""
    q1 = split(half_pi, 16, mp.floor)
    q2 = split(half_pi - q1, 16, mp.floor)
    q3 = to_f32(half_pi - q1 - q2)
    for q in (q1, q2, q3):
        assert to_f32(q) == q and q > 0
    tail = half_pi - q1 - q2 - q3
    two_over_pi = to_f32(2 / mp.pi)
    bits = struct.unpack("<I", struct.pack("<f", float(two_over_pi)))[0]
    print()
    print(f"/// 2/pi rounded to f32 ({rust_f32(two_over_pi)}, bits {bits:#010x}: core's constant);")
    print("/// `x * FRAC_2_PI_F32` picks the f32 routines' quadrant count k.")
    print("pub const FRAC_2_PI_F32: f32 = core::f32::consts::FRAC_2_PI;")
    print("/// The bits of 2/pi rounded to f32, as computed here; a unit test holds core's constant to it.")
    print("#[cfg(test)]")
    print(f"pub const FRAC_2_PI_F32_BITS: u32 = {bits:#010x};")
    print("/// pi/2 rounded down to 16 significant bits: `k * PIO2_F32_1` is exact in f32 for |k| < 2^8.")
    print(f"pub const PIO2_F32_1: f32 = {rust_f32(q1)};")
    print("/// The next 16 bits of pi/2, rounded down.")
    print(f"pub const PIO2_F32_2: f32 = {rust_f32(q2)};")
    print(f"/// The rest of pi/2 rounded to f32; pi/2 - (PIO2_F32_1 + .. + PIO2_F32_3) = {mp.nstr(tail, 3)}.")
    print(f"pub const PIO2_F32_3: f32 = {rust_f32(q3)};")
    r32 = mp.pi / 4 * (1 + mp.mpf("1e-4"))
    zmax = r32 * r32
    zlow = zmax * mp.mpf("1e-4")
    for name, f, w, weighting, what in (
        ("SIN_F32", sin_tail, sin_weight, sin_w, "sin(r) = r + r^3 * S(r^2), f32 kernel"),
        ("COS_F32", cos_tail, cos_weight, cos_w, "cos(r) = 1 - r^2/2 + r^4 * C(r^2), f32 kernel"),
    ):
        print()
        rounded, level = fit_rounded(f, w, zlow, zmax, 3, to_f32)
        after = max_error(f, w, rounded, zlow, zmax)
        print(f"/// Minimax coefficients of {what} (evaluated in f32), lowest power first, on r in")
        print(f"/// [0, pi/4 (1 + 1e-4)], {weighting}. Error of the unrounded fit: {mp.nstr(level, 3)};")
        print(f"/// with the coefficients rounded to f32 (one at a time, the rest refitted): {mp.nstr(after, 3)}.")
        print(f"pub const {name}: [f32; 3] = [")
        for c in rounded:
            print(f"    {rust_f32(c)},")
        print("];")


if __name__ == "__main__":
    main()
