#!/usr/bin/env python3
"""Writes the binary seed inputs of the numeric fuzz targets into tests/fuzz/corpus/NAME/.

The bytes follow baize::fuzz::FuzzInput (tests/fuzz/fuzz_support.h) in the order each target reads
them, so every seed is a named, physically meaningful case the fuzzers mutate from. Run it from
anywhere; it overwrites only the seed_*.bin files it writes. Files the fuzzers add (named by their
hash) are kept.
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
WORD_MAX = 0xFFFFFFFF
TYPICAL = 0xFF  # a leading byte >= 48: a value of the caller's typical magnitude
EDGE = 16  # a leading byte in [16, 48): one of FuzzInput's edge values, chosen by the next byte
EDGE_INDEX = {"0": 0, "-0": 1, "nan": 2, "inf": 3, "-inf": 4, "denorm_min": 5, "min": 6,
              "max": 7, "-max": 8, "eps": 9, "1e-300": 10, "1e300": 11, "scale": 12}


def byte(b):
    return bytes([b & 0xFF])


def word(w):
    return struct.pack(">I", w & WORD_MAX)


def value(v, scale, signed=True):
    """FuzzInput::value(scale, signed) giving v (to 32-bit resolution)."""
    if isinstance(v, str):
        return byte(EDGE) + byte(EDGE_INDEX[v])
    u = (v / scale + 1) / 2 if signed else v / scale
    if not 0 <= u <= 1:  # out of the typical range: the raw double
        return byte(0) + struct.pack(">d", v)
    return byte(TYPICAL) + word(round(u * WORD_MAX))


def integer(n, lo, hi):
    """FuzzInput::integer(lo, hi) giving n."""
    return word(n - lo)


def in_range(v, lo, hi):
    """FuzzInput::inRange(lo, hi) giving v."""
    return byte(2) + word(round((v - lo) / (hi - lo) * WORD_MAX))


def write(target, name, data):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "seed_" + name + ".bin"), "wb") as f:
        f.write(data)


# ---- polynomial_roots: coefficients (direct or from roots), then the interval -------------------

def direct(coefficients, lo, hi):
    data = byte(0)
    for c in coefficients:
        if isinstance(c, str) or c == 0:
            data += value(c if isinstance(c, str) else "0", 1.0) + integer(0, -70, 70)
        else:
            m, e = math.frexp(c)  # c = m 2^e, |m| in [0.5, 1)
            data += value(m, 1.0) + integer(e, -70, 70)
    return data + value(lo, 4.0) + byte(1) + value(hi - lo, 4.0)


def from_roots(leading, roots, lo, hi, how=None):
    """how[i]: 0 a new root roots[i], 1 the previous root again, 2 nearly the previous root."""
    how = how or [0] * len(roots)
    data = byte(1) + integer(len(roots), 0, 4)
    for i, r in enumerate(roots):
        if i > 0:
            data += byte(how[i])
        if how[i] == 0:
            data += value(r, 4.0)
        elif how[i] == 2:
            data += integer(r, 1, 60)  # r: the offset's power of two below the previous root
    return data + value(leading, 1.0) + value(lo, 4.0) + byte(1) + value(hi - lo, 4.0)


write("polynomial_roots", "four_simple_roots", from_roots(1.0, [0.5, 1.5, 2.5, 3.5], 0, 4))
write("polynomial_roots", "double_root", from_roots(0.5, [1.0, 0], 0, 2, how=[0, 1]))
write("polynomial_roots", "two_double_roots",
      from_roots(1.0, [1.0, 0, 2.0, 0], 0, 3, how=[0, 1, 0, 1]))
write("polynomial_roots", "nearly_double_root", from_roots(1.0, [1.0, 30], 0, 2, how=[0, 2]))
write("polynomial_roots", "vanishing_leading_coefficient", direct([-1.0, 2.0, 0, 0, 0], -1, 1))
write("polynomial_roots", "huge_and_tiny_coefficients", direct([-1e-300, 0, 1e-290, 0, 0], 0, 1))
write("polynomial_roots", "gap_closing_quadratic", direct([0.25, -1.0, 0.5, 0, 0], 0, 4))
write("polynomial_roots", "nan_coefficient", direct([1.0, "nan", 1.0, 0, 0], 0, 1))
write("polynomial_roots", "zero_polynomial", direct([0, 0, 0, 0, 0], 0, 1))

# ---- cushion_solver: m, R, h/R - 1, e, mu_w, mu_s; v; (v_z); w; options; paper steps; simple e --

def cushion(v, w, m=0.1406, R=0.02625, h_over_R=1.4, e=0.98, mu_w=0.14, mu_s=0.212,
            tolerance=None, paper_steps=100, simple_e=0.91, v_z=None):
    data = value(m, 0.2, False) + value(R, 0.03, False) + value(h_over_R - 1, 1.0, False)
    data += value(e, 1.0, False) + value(mu_w, 0.5, False) + value(mu_s, 0.5, False)
    data += value(v[0], 5.0) + value(v[1], 5.0, False)
    data += byte(0) + value(v_z, 1.0) if v_z is not None else byte(1)
    spin = 5.0 / 0.03
    data += value(w[0], spin) + value(w[1], spin) + value(w[2], spin)
    data += byte(0) + value(tolerance, 1e-6, False) if tolerance is not None else byte(1)
    return data + integer(paper_steps, -2, 300) + value(simple_e, 1.0, False)


R = 0.02625
write("cushion_solver", "head_on_rolling", cushion([0, 1.0], [-1.0 / R, 0, 0]))
a = math.radians(30)
write("cushion_solver", "thirty_degrees_topspin_sidespin",
      cushion([1.5 * math.cos(a), 1.5 * math.sin(a)], [-1.5 / R * math.sin(a),
                                                         1.5 / R * math.cos(a), -2 * 1.5 / R]))
write("cushion_solver", "frictionless", cushion([0.3, 1.0], [0, 0, 0], mu_w=0, mu_s=0))
write("cushion_solver", "zero_slip_at_cushion_and_cloth",  # rolling, nose slip cancelled by w_z
      cushion([0, 1.0], [-1.0 / R, 0, 0], h_over_R=1.4, e=1.0))
write("cushion_solver", "grazing", cushion([2.0, 1e-6], [0, 2.0 / R, 0], tolerance=1e-2))
write("cushion_solver", "nan_spin", cushion([0, 1.0], ["nan", 0, 0]))
write("cushion_solver", "lifted_ball", cushion([0, 1.0], [0, 0, 0], v_z=0.5))

# ---- ball_ball: model, R, m1, (m2), e, law, a, b, c, mu, mu_b, mu_s, (tol), (steps), balls, n -----

def ball(v, w):
    spin = 5.0 / 0.028575
    return (value(v[0], 5.0) + value(v[1], 5.0) + byte(1) + value(w[0], spin) +
            value(w[1], spin) + value(w[2], spin))


def ball_ball(model, v1, w1, v2, w2, angle, law=0, e=0.95, mu_b=0.05, mu_s=0.212, steps=None):
    data = integer(model, 0, 2) + value(0.028575, 0.03, False) + value(0.17, 0.2, False)
    data += byte(0) + value(e, 1.0, False) + integer(law, 0, 2)
    data += value(9.951e-3, 0.05, False) + value(0.108, 0.5, False) + value(1.088, 2.0, False)
    data += value(0.06, 0.5, False) + value(mu_b, 0.2, False) + value(mu_s, 0.5, False)
    data += byte(1)  # the default tolerance
    data += byte(0) + integer(steps, -2, 300) if steps is not None else byte(1)
    return data + ball(v1, w1) + ball(v2, w2) + byte(1) + value(angle, 3.2)


Rp = 0.028575
write("ball_ball", "head_on_stun", ball_ball(0, [2.0, 0], [0, 0, 0], [0, 0], [0, 0, 0], 0.0))
write("ball_ball", "half_ball_rolling",
      ball_ball(0, [2.0, 0], [0, 2.0 / Rp, 0], [0, 0], [0, 0, 0], math.radians(30)))
write("ball_ball", "mathavan_follow",
      ball_ball(1, [1.5, 0], [0, 1.5 / Rp, 3.0], [0, 0], [0, 0, 0], math.radians(20)))
write("ball_ball", "mathavan_euler",
      ball_ball(1, [1.5, 0], [0, -1.5 / Rp, 0], [0, 0], [0, 0, 0], 0.3, steps=50))
write("ball_ball", "constant_friction_both_moving",
      ball_ball(0, [1.0, 0.5], [0, 0, 20.0], [-0.5, 0.2], [10.0, 0, 0], 0.1, law=1))
write("ball_ball", "separating", ball_ball(0, [-1.0, 0], [0, 0, 0], [0, 0], [0, 0, 0], 0.0))

# ---- simulate: models, cloth, table, balls ----------------------------------------------------

def sim_ball(placement, where, v, w, tiny=False):
    """placement 0: frozen (where = (angle, gap or None)), 1: at a cushion (where = (side, y)),
    3: anywhere inside (where = (x, y) as fractions of the half sizes)."""
    data = byte(placement)
    if placement == 0:
        angle, gap = where
        data += in_range(angle, -math.pi, math.pi)
        data += byte(0) if gap is None else byte(1) + value(gap, 1e-7, False)
    elif placement == 1:
        side, y = where
        data += byte(0 if side > 0 else 1) + in_range(y, -1, 1)
    else:
        data += in_range(where[0], -1, 1) + in_range(where[1], -1, 1)
    scale = 1e-3 if tiny else 8.0
    data += byte(0 if tiny else 1) + value(v[0], scale) + value(v[1], scale) + byte(1)
    spin = 3 * scale / Rp
    return data + value(w[0], spin) + value(w[1], spin) + value(w[2], spin)


def simulate(balls, cushion_model=0, ball_model=0, length=2.54, width=1.27, steps=100):
    data = integer(cushion_model, 0, 2) + integer(steps, 1, 300) + integer(ball_model, 0, 1)
    data += byte(1)  # pool cloth
    data += in_range(length, 4.5 * Rp, 4.0) + in_range(width, 2.5 * Rp, length)
    data += integer(len(balls), 1, 4)
    return data + b"".join(balls)


write("simulate", "head_on_two_balls", simulate([
    sim_ball(3, (-0.5, 0), [3.0, 0], [0, 0, 0]), sim_ball(3, (0.5, 0), [0, 0], [0, 0, 0])]))
write("simulate", "frozen_line_of_three", simulate([
    sim_ball(3, (-0.6, 0.1), [4.0, 0], [0, 50.0, 0]), sim_ball(3, (0.2, 0.1), [0, 0], [0, 0, 0]),
    sim_ball(0, (0.0, None), [0, 0], [0, 0, 0])]))
write("simulate", "ball_against_cushion", simulate([
    sim_ball(1, (1, 0.3), [-0.5, 2.0], [0, 0, 80.0])], cushion_model=1))
write("simulate", "tiny_speeds", simulate([
    sim_ball(3, (0, 0), [5e-4, 2e-4], [0, 0, 0.1], tiny=True),
    sim_ball(0, (0.5, 1e-8), [0, 0], [0, 0, 0])], ball_model=1))
write("simulate", "simple_cushions_many_banks", simulate([
    sim_ball(3, (0.3, -0.4), [6.0, 5.0], [20.0, -30.0, 100.0])], cushion_model=2))
