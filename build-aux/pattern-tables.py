#!/usr/bin/env python3
"""pattern-tables.py: writes kernels/pattern_tables.cl, the tables POV-Ray 3.7
builds at start-up for its noise and cell patterns, so that kernels/pattern.cl
gives POV-Ray's values at the same points.

    python3 build-aux/pattern-tables.py > kernels/pattern_tables.cl

Not run by the build: its output is committed. How POV-Ray 3.7 makes each table
(source/backend/texture/texture.cpp, source/backend/pattern/pattern.cpp and
source/backend/support/randomsequences.cpp of the 3.7-stable branch):

 * Its generator is the 32-bit LCG  r = r * 1812433253 + 12345  (mod 2^32),
   each draw being bits 16-30 of r.
 * hashTable: 0..4095, shuffled from the last entry down: entry i swaps with
   entry (draw % 4096), the LCG starting from r = 0. POV-Ray doubles it to 8192
   entries; every index the kernels form is reduced mod 4096 instead.
 * RTable: 267 constants in POV-Ray's source (interleaved there with halves of
   themselves, which the kernel recomputes).
 * The gradients of noise_generator 3: 2048 vectors, each of three draws
   ((draw % 4096) - 2048) / 2048 redrawn while its squared length is > 1 or
   < 1e-5, then normalized; the LCG starts from r = 1. The same LCG then shuffles
   the permutation 0..2047 (plus an entry 2048 holding 0): for i = 2048, 2046,
   ... 2, entry i swaps with entry (draw % 2048). Both tables are then repeated
   with period 2048 (entry 2048 is overwritten), so 2048 entries of each suffice.
 * PatternRands (cells, crackle): boost's mt19937 with its default seed 5489,
   each 32-bit output x giving the double x / 2^32 (boost::uniform_real(0, 1)).
   The indices used are hash values (< 4096) plus at most 2: 4098 entries.
"""

RTABLE = [
    -1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593,
    0.432334, 0.103685, 0.590539, 0.0286412, 0.46981, -0.84622,
    -0.0734112, -0.304097, -0.40206, -0.210132, -0.919127, 0.652033,
    -0.83151, -0.183948, -0.671107, 0.852476, 0.043595, -0.404532,
    0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195,
    0.899474, 0.490623, 0.221729, -0.400381, -0.853727, -0.932586,
    0.659113, 0.961303, 0.325948, -0.750851, 0.842466, 0.734401,
    -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028,
    -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408,
    -0.90396, -0.686549, -0.785214, 0.488548, 0.0246433, 0.142473,
    -0.602136, 0.375845, -0.00779736, 0.498955, -0.268147, 0.856382,
    -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388,
    -0.767971, -0.314748, 0.824308, -0.342092, 0.721431, -0.24004,
    -0.63653, 0.553277, 0.376272, 0.158984, -0.452659, 0.396323,
    -0.420676, -0.454154, 0.122179, 0.295857, 0.0664225, -0.202075,
    -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516,
    -0.697139, 0.742702, -0.900786, 0.471489, -0.133532, 0.119127,
    -0.889769, -0.23183, -0.669673, -0.046891, -0.803433, -0.966735,
    0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647,
    -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908,
    0.480797, 0.535668, -0.250172, -0.83093, -0.653773, -0.443809,
    0.119982, -0.897642, 0.89453, 0.165789, 0.633875, -0.886839,
    0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469,
    -0.598779, 0.929656, -0.170794, -0.537163, 0.312581, 0.959442,
    0.722652, 0.499931, 0.175616, -0.534874, -0.685115, 0.444999,
    0.17171, 0.108202, -0.768704, -0.463828, 0.254231, 0.546014,
    0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184,
    -0.33138, -0.629206, 0.0606546, 0.722866, -0.0979477, 0.821561,
    0.0931258, -0.972808, 0.0318151, -0.867033, -0.387228, 0.280995,
    -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974,
    0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132,
    0.581079, 0.209461, -0.317433, -0.284993, 0.181323, 0.341634,
    0.804959, -0.229572, -0.758907, -0.336721, 0.605463, -0.991272,
    -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686,
    0.439078, 0.66128, 0.694514, 0.0565042, 0.54342, -0.438804,
    -0.0228428, -0.687068, 0.857267, 0.301991, -0.494255, -0.941039,
    0.775509, 0.410575, -0.362081, -0.671534, -0.348379, 0.932433,
    0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444,
    -0.848112, 0.724697, 0.473503, 0.998749, 0.174701, 0.559625,
    -0.029099, -0.337392, -0.958129, -0.659785, 0.236042, -0.246937,
    0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481,
    -0.420127, -0.427878, 0.566186,
]
assert len(RTABLE) == 267


class Lcg:
    def __init__(self, seed):
        self.r = seed & 0xFFFFFFFF

    def draw(self):
        self.r = (self.r * 1812433253 + 12345) & 0xFFFFFFFF
        return (self.r >> 16) & 0x7FFF


def hash_table():
    h = list(range(4096))
    g = Lcg(0)
    for i in range(4095, -1, -1):
        j = g.draw() % 4096
        h[i], h[j] = h[j], h[i]
    return h


def solid_noise_tables():
    n = 2048
    g = Lcg(1)
    grads = []
    for _ in range(n):
        while True:
            v = [((g.draw() % (2 * n)) - n) / n for _ in range(3)]
            s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2]
            if not (s > 1.0 or s < 1.0e-5):
                break
        s = 1.0 / s ** 0.5
        grads.append([c * s for c in v])
    perm = list(range(n)) + [0]
    for i in range(n, 0, -2):
        k = perm[i]
        j = g.draw() % n
        perm[i] = perm[j]
        perm[j] = k
    return grads, perm[:n]


def mt19937(count, seed=5489):
    mt = [0] * 624
    mt[0] = seed
    for i in range(1, 624):
        mt[i] = (1812433253 * (mt[i - 1] ^ (mt[i - 1] >> 30)) + i) & 0xFFFFFFFF
    idx = 624
    out = []
    while len(out) < count:
        if idx >= 624:
            for i in range(624):
                y = (mt[i] & 0x80000000) | (mt[(i + 1) % 624] & 0x7FFFFFFF)
                mt[i] = mt[(i + 397) % 624] ^ (y >> 1) ^ (0x9908B0DF if y & 1 else 0)
            idx = 0
        y = mt[idx]
        idx += 1
        y ^= y >> 11
        y ^= (y << 7) & 0x9D2C5680
        y ^= (y << 15) & 0xEFC60000
        y ^= y >> 18
        out.append(y)
    return out


def emit(name, ctype, values, fmt, per_line):
    print("constant %s %s[%d] = {" % (ctype, name, len(values)))
    for i in range(0, len(values), per_line):
        print("\t" + ", ".join(fmt(v) for v in values[i:i + per_line]) + ",")
    print("};")


def f(v):
    s = "%.9g" % v
    if "." not in s and "e" not in s:
        s += ".0"
    return s + "f"


def main():
    mt = mt19937(4098)
    assert mt[0] == 3499211612  # std::mt19937's first output with the default seed
    grads, perm = solid_noise_tables()
    print("/* pattern_tables.cl: POV-Ray 3.7's noise and cell tables, as it builds them")
    print(" * at start-up. Generated by build-aux/pattern-tables.py (which says how):")
    print(" * do not edit. Read by kernels/pattern.cl. */")
    print()
    print("/* hashTable: a permutation of 0..4095 (POV-Ray's 8192 entries repeat it). */")
    emit("pattern_hash", "ushort", hash_table(), str, 16)
    print()
    print("/* RTable's 267 constants; POV-Ray interleaves each with its half. */")
    emit("pattern_rtable", "float", RTABLE, f, 8)
    print()
    print("/* noise_generator 3: the permutation and unit gradients, period 2048. */")
    emit("pattern_perm", "ushort", perm, str, 16)
    emit("pattern_grad", "float", [c for g in grads for c in g], f, 6)
    print()
    print("/* PatternRands: mt19937 (seed 5489) outputs / 2^32, the first 4098. */")
    emit("pattern_rands", "float", [x / 4294967296.0 for x in mt], f, 8)


main()
