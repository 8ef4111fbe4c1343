#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Derive the standard 2-braid ODEs (paper Sect. 12.2) with sympy, check the
derivation, and write the C right-hand sides and exact Jacobians.

Needs sympy and mpmath: on Debian/Ubuntu the package python3-sympy (it pulls
in python3-mpmath), installed with `sudo apt-get install python3-sympy`, for
the system interpreter /usr/bin/python3 (the committed output was made with
sympy 1.11.1, Debian 12).  The build itself needs only a C compiler: the
generated files are committed.

Usage (from the repository root):

    /usr/bin/python3 scripts/gen_braid.py            # checks, then writes the C files
    /usr/bin/python3 scripts/gen_braid.py --check    # checks only

then `make check`.  With the same sympy version the output is byte-identical
to the committed files (`git status` shows nothing); another version may
order the common subexpressions differently, which is harmless but shows in
the diff.

Output: equations/braid_rhs_gen.c and equations/braid_rhs_gen.h, and the AUTO-07p
equation file tests/auto07p/knot72auto.c (the same right-hand side under AUTO's C
interface, with the template scripts/auto_braid_knot.c.in; make bench runs it).  The output
is deterministic (the script re-executes itself with PYTHONHASHSEED=0 so that
sympy's common-subexpression elimination sees the same term order every run).
The derivation is written out in doc/braid-equations.md; the section numbers
below (D1, D2, ...) refer to it.
"""

import os
import sys

if os.environ.get("PYTHONHASHSEED") != "0":
    os.environ["PYTHONHASHSEED"] = "0"
    os.execv(sys.executable, [sys.executable] + sys.argv)

import random  # noqa: E402

import mpmath  # noqa: E402
import sympy as sp  # noqa: E402
from sympy.printing.c import C99CodePrinter  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# ---------------------------------------------------------------------------
# Symbols.  The state order is equations/braid_state.h; the material order is
# braid_material (Delta, B1, B2, C1, C2, w01, w02).
# ---------------------------------------------------------------------------
STATE_NAMES = ["F1", "F2", "F3", "M1", "M2", "M3", "eta", "w2", "w3", "xi1", "T1",
               "xi2", "T2", "q0", "q1", "q2", "q3", "rx", "ry", "rz", "sig"]
MAT_NAMES = ["Delta", "B1", "B2", "C1", "C2", "w01", "w02"]
U = sp.symbols(" ".join(STATE_NAMES), real=True)
(F1, F2, F3, M1, M2, M3, eta, w2, w3, xi1, T1, xi2, T2,
 q0, q1, q2, q3, rx, ry, rz, sig) = U
P = sp.symbols(" ".join(MAT_NAMES), real=True)
Delta, B1, B2, C1, C2, w01, w02 = P
NDIM = len(U)
NMAT = len(P)

# arguments of g (Eq. 12.2.21) treated as independent variables
etap_s, xi1p_s, xi2p_s, h_s = sp.symbols("etap xi1p xi2p h", real=True)

ce, se = sp.cos(eta), sp.sin(eta)
te = se / ce
omd = 1 - Delta * w3  # 1 - Delta*omega3 = sigma' cos(eta) > 0 in the physical domain


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


# D2: elastic energy density, Eq. (12.2.22), second line (the form we use)
g_e = sp.Rational(1, 2) * (
    B1 * (w2**2 + w3**2)
    + B2 * (ce / omd * (w2 + etap_s)**2 + (w3 - se**2 / Delta)**2 / (omd * ce))
    + C1 * ((w3 - 1 / Delta) * te - xi1p_s - w01)**2
    + C2 * (ce / omd * (se / Delta - xi2p_s)**2 + 2 * w02 * (se / Delta - xi2p_s)
            + w02**2 * omd / ce))
# Eq. (12.2.21)
g = g_e + h_s * omd / ce - F1

# D3: algebraic relations
w1 = -omd * te / Delta                     # (12.2.8): (omega3 - 1/Delta) tan(eta)
sigmap = omd / ce                          # (12.2.6) with (12.2.7), cos(eta) > 0
etap = (M2 - B1 * w2) * omd / (B2 * ce) - w2   # M2 = dg/domega2 (12.2.19)
xi1p = w1 - w01 + T1 / C1                  # T1 = dg/dxi1'
xi2p = se / Delta + sigmap * (T2 / C2 + w02)   # T2 = dg/dxi2'
SUB = {etap_s: etap, xi1p_s: xi1p, xi2p_s: xi2p}

# h from M3 + tan(eta) M1 = dg/domega3 (D3)
h_expr = ce / Delta * (sp.diff(g_e, w3).subs(SUB) - M3 - te * M1)

# D4: balance laws (12.2.12)-(12.2.13) with t1 = (1,0,0) in the braid frame
om = [w1, w2, w3]
Fv = [F1, F2, F3]
Mv = [M1, M2, M3]
Fp = [-c for c in cross(om, Fv)]
wxM = cross(om, Mv)
Mp = [-wxM[0], -wxM[1] + F3, -wxM[2] - F2]

# D5: omega2' from (12.2.18) with dg/deta' = M2 - B1 omega2
dg_deta = (sp.diff(g_e, eta) + h_s * sp.diff(omd / ce, eta)).subs(SUB).subs(h_s, h_expr)
w2p = (Mp[1] - dg_deta + M1 * (Delta * w3 - 1) / (Delta * ce**2)) / B1

# D6: omega3' from d/ds h = 0
known_rates = {F1: Fp[0], F2: Fp[1], F3: Fp[2], M1: Mp[0], M2: Mp[1], M3: Mp[2],
               eta: etap, w2: w2p, T1: sp.Integer(0), T2: sp.Integer(0)}
w3_den = sp.diff(h_expr, w3)
w3_num = sum(sp.diff(h_expr, k) * v for k, v in known_rates.items())
w3p = -w3_num / w3_den
W3_DEN_CLOSED = ce / Delta * (B1 + B2 * ce**3 / omd**3)

# D7: kinematics (12.2.23), r1' = t1(q), sigma'
qv = [q0, q1, q2, q3]
Aq = sp.Matrix([[0, -w1, -w2, -w3], [w1, 0, w3, -w2], [w2, -w3, 0, w1], [w3, w2, -w1, 0]])
qp = list(sp.Rational(1, 2) * Aq * sp.Matrix(qv))
t1q = [q0**2 + q1**2 - q2**2 - q3**2, 2 * q1 * q2 + 2 * q0 * q3, 2 * q1 * q3 - 2 * q0 * q2]
d1q = [2 * q1 * q2 - 2 * q0 * q3, q0**2 - q1**2 + q2**2 - q3**2, 2 * q2 * q3 + 2 * q0 * q1]
u1q = [2 * q1 * q3 + 2 * q0 * q2, 2 * q2 * q3 - 2 * q0 * q1, q0**2 - q1**2 - q2**2 + q3**2]

RHS = (Fp + Mp + [etap, w2p, w3p, xi1p, sp.Integer(0), xi2p, sp.Integer(0)]
       + qp + t1q + [sigmap])
assert len(RHS) == NDIM

# D8: first integrals
ham = (dot(Mv, om) + (M2 - B1 * w2) * etap + T1 * xi1p + T2 * xi2p
       - g_e.subs(SUB) - h_expr * sigmap + F1)
INTEGRALS = [F1**2 + F2**2 + F3**2, dot(Fv, Mv), h_expr,
             q0**2 + q1**2 + q2**2 + q3**2, T1, T2, ham]

AUX = [w1, sigmap, etap, xi1p, xi2p, h_expr, w3_den]

# partials of g at given strains (h given, F1 left out of the value)
GP_ARGS = [eta, etap_s, w2, w3, xi1p_s, xi2p_s, h_s]
g_noF = g_e + h_s * omd / ce
GPARTIALS = [g_noF, sp.diff(g_noF, w2), sp.diff(g_noF, w3), sp.diff(g_noF, eta),
             sp.diff(g_noF, etap_s), sp.diff(g_noF, xi1p_s), sp.diff(g_noF, xi2p_s)]

# ---------------------------------------------------------------------------
# D9: contact pressure.  Strand moments and forces in the first braid frame.
# up[j] = u_j', upp[j] = u_j'' (derivatives along s).
# ---------------------------------------------------------------------------
UP = sp.symbols(" ".join("d_" + n for n in STATE_NAMES), real=True)
UPP = sp.symbols(" ".join("dd_" + n for n in STATE_NAMES), real=True)


def dtot(expr):
    """d/ds of an expression in (u, u'), given u' = UP and u'' = UPP."""
    r = 0
    for k in range(NDIM):
        r += sp.diff(expr, U[k]) * UP[k] + sp.diff(expr, UP[k]) * UPP[k]
    return r


def dframe(v):
    """Inertial derivative of a vector given by its braid-frame components."""
    wxv = cross(om, v)
    return [dtot(v[i]) + wxv[i] for i in range(3)]


t2v = [ce, 0, -se]
u2v = [se, 0, ce]
Om2 = w2 + etap
Om3 = (w3 - se**2 / Delta) / ce
m1v = [-T1, B1 * w2, B1 * w3]
m2v = [T2 * t2v[i] + B2 / sigmap * (Om2 * (1 if i == 1 else 0) + Om3 * u2v[i]) for i in range(3)]
Kv = [Mv[i] - m1v[i] - m2v[i] for i in range(3)]   # = Delta d1 x n2
n2_t = -Kv[2] / Delta                               # n2 . t1
n2_u = Kv[0] / Delta                                # n2 . u1
Dm2 = dframe(m2v)
n2_d = -dot(u2v, Dm2) / sigmap                      # strand 2 moment balance, u2 part
n2v = [n2_t, n2_d, n2_u]
Dn2 = dframe(n2v)
p_from2 = -Dn2[1]                                   # n2' = -p d1 (per unit s)
Dm1 = dframe(m1v)
n1v = [F1 - n2_t, -Dm1[2], Dm1[1]]                  # strand 1 moment balance
Dn1 = dframe(n1v)
p_from1 = Dn1[1]                                    # n1' = +p d1
PRESSURE = [p_from1, p_from2, n1v[0], n1v[1], n1v[2], n2v[0], n2v[1], n2v[2], Dn2[0], Dn2[2],
            sigmap]


# ---------------------------------------------------------------------------
# Checks of the derivation (each prints one line; a failure aborts).
# ---------------------------------------------------------------------------
def check(name, ok):
    print(("verified: " if ok else "FAILED:   ") + name)
    if not ok:
        sys.exit(1)


def check_g_lines():
    """(12.2.22): the printed second line equals the first line built from the
    frame relations (12.2.3)-(12.2.5) and sigma' from (12.2.6)."""
    s = sp.Symbol("s")
    w1f = sp.Symbol("w1f", real=True)
    etaf, xi1f, xi2f = (sp.Function(n)(s) for n in ("etaf", "xi1f", "xi2f"))

    def R1(a):
        return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])

    def R2(a):
        return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])

    def hat(v):
        return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])

    def vee(W):
        return [W[2, 1], W[0, 2], W[1, 0]]

    omv = [w1f, w2, w3]
    A = R1(xi1f)
    omt = vee(sp.simplify(A * (hat(omv) - A.T * A.diff(s)) * A.T))          # (12.2.3)
    Om = vee(sp.simplify(R2(etaf).T * hat(omv) * R2(etaf) + R2(etaf).T * R2(etaf).diff(s)))
    Bm = R1(xi2f)
    Omt = vee(sp.simplify(Bm.T * hat(Om) * Bm + Bm.T * Bm.diff(s)))          # (12.2.5)
    sig6 = sp.sqrt((Delta * w1f)**2 + (Delta * w3 - 1)**2)                   # (12.2.6)
    line1 = sp.Rational(1, 2) * (B1 * (omt[1]**2 + omt[2]**2)
                                 + B2 / sig6 * (Omt[1]**2 + Omt[2]**2)
                                 + C1 * (omt[0] - w01)**2
                                 + C2 / sig6 * (Omt[0] - sig6 * w02)**2)
    rep = {sp.Derivative(etaf, s): etap_s, sp.Derivative(xi1f, s): xi1p_s,
           sp.Derivative(xi2f, s): xi2p_s}
    line1 = line1.subs(rep).subs({etaf: eta, xi1f: xi1, xi2f: xi2})
    line1 = line1.subs(w1f, w1)
    sig6e = sig6.subs(w1f, w1)
    check("(12.2.6)+(12.2.8): sigma'^2 = ((1 - Delta w3)/cos eta)^2",
          sp.simplify(sig6e**2 - sigmap**2) == 0)
    check("(12.2.7): sin eta = -Delta w1/sigma', cos eta = (1 - Delta w3)/sigma'",
          sp.simplify(-Delta * w1 / sigmap - se) == 0 and sp.simplify(omd / sigmap - ce) == 0)
    line1 = line1.subs(sig6e, sigmap)
    check("(12.2.22) first line contains no square root after sigma' = (1-Delta w3)/cos eta",
          not any(a.exp == sp.Rational(1, 2) for a in line1.atoms(sp.Pow)))
    check("(12.2.22) second line = first line built from (12.2.3)-(12.2.6)",
          sp.simplify(sp.expand_trig(line1 - g_e)) == 0)
    # the strand 2 strains used in D9 are the ones of (12.2.4)
    check("Omega2 = w2 + eta', Omega3 = (w3 - sin^2 eta/Delta)/cos eta, Omega1 = -sin eta/Delta",
          sp.simplify(Om[1].subs(rep) - (w2 + etap_s)) == 0
          and sp.simplify(Om[2].subs(rep).subs(etaf, eta).subs(w1f, w1) - Om3) == 0
          and sp.simplify(Om[0].subs(etaf, eta).subs(w1f, w1) + se / Delta) == 0)


def check_eta_chain_rule():
    """(12.2.18), (12.2.20): d eta/d omega1, d eta/d omega3 from (12.2.7)."""
    a1, a3 = sp.symbols("a1 a3", real=True)
    et = sp.atan(-Delta * a1 / (1 - Delta * a3))   # tan eta = -Delta w1/(1 - Delta w3)
    e1 = sp.diff(et, a1)
    e3 = sp.diff(et, a3)
    # evaluate at a1 = w1(eta, w3), a3 = w3
    e1 = e1.subs({a1: w1, a3: w3})
    e3 = e3.subs({a1: w1, a3: w3})
    check("d eta/d omega1 = Delta cos^2 eta/(Delta w3 - 1)",
          sp.simplify(e1 - Delta * ce**2 / (Delta * w3 - 1)) == 0)
    check("d eta/d omega3 = -Delta sin eta cos eta/(Delta w3 - 1)",
          sp.simplify(e3 + Delta * se * ce / (Delta * w3 - 1)) == 0)


def check_inversions():
    check("M2 = dg/domega2 at eta'(u)", sp.simplify(sp.diff(g, w2).subs(SUB) - M2) == 0)
    check("M2 - B1 w2 = dg/deta' at eta'(u)",
          sp.simplify(sp.diff(g, etap_s).subs(SUB) - (M2 - B1 * w2)) == 0)
    check("T1 = dg/dxi1' at xi1'(u)", sp.simplify(sp.diff(g, xi1p_s).subs(SUB) - T1) == 0)
    check("T2 = dg/dxi2' at xi2'(u)", sp.simplify(sp.diff(g, xi2p_s).subs(SUB) - T2) == 0)
    check("M3 + tan(eta) M1 = dg/domega3 at h(u)",
          sp.simplify((sp.diff(g, w3).subs(SUB).subs(h_s, h_expr)) - (M3 + te * M1)) == 0)
    check("omega3' denominator dh/domega3 = (cos eta/Delta)(B1 + B2 cos^3 eta/(1-Delta w3)^3)",
          sp.simplify(w3_den - W3_DEN_CLOSED) == 0)
    check("h does not depend on C1, w01 (C1 (omega1-xi1'-w01) = -T1)",
          sp.simplify(sp.diff(h_expr, C1)) == 0 and sp.simplify(sp.diff(h_expr, w01)) == 0)


def check_quaternions():
    """(12.2.23) is R(q)' = R(q) hat(omega) for R = (t1, d1, u1)."""
    R = sp.Matrix([[t1q[i], d1q[i], u1q[i]] for i in range(3)])
    Rp = sp.zeros(3, 3)
    for k in range(4):
        Rp += R.diff(qv[k]) * qp[k]
    W = sp.Matrix([[0, -om[2], om[1]], [om[2], 0, -om[0]], [-om[1], om[0], 0]])
    check("(12.2.23): d/ds (t1,d1,u1) = (t1,d1,u1) hat(omega) (any |q|)",
          sp.simplify(Rp - R * W) == sp.zeros(3, 3))
    check("(12.2.23): q.q' = 0 identically", sp.simplify(dot(qv, qp)) == 0)


def check_integrals_numeric():
    """dI/ds = grad(I).rhs vanishes for every first integral.  |F|^2, F.M,
    |q|^2, T1, T2 symbolically; h and the Hamiltonian at random points in
    50-digit arithmetic (the symbolic simplification is slow)."""
    for name, k in (("|F|^2", 0), ("F.M", 1), ("|q|^2", 3), ("T1", 4), ("T2", 5)):
        d = sum(sp.diff(INTEGRALS[k], U[j]) * RHS[j] for j in range(NDIM))
        check("d/ds %s = 0 symbolically" % name, sp.simplify(d) == 0)
    grads = {}
    for name, k in (("h", 2), ("Hamiltonian", 6)):
        grads[name] = [sp.diff(INTEGRALS[k], U[j]) for j in range(NDIM)]
    rng = random.Random(12345)
    mpmath.mp.dps = 50
    worst = {"h": 0.0, "Hamiltonian": 0.0}
    for _ in range(5):
        vals = {}
        for j, x in enumerate(U):
            vals[x] = sp.Float(rng.uniform(-1.0, 1.0), 50)
        vals[eta] = sp.Float(rng.uniform(-0.6, 0.6), 50)
        vals[w3] = sp.Float(rng.uniform(-2.0, 3.0), 50)
        mvals = {Delta: sp.Float(rng.uniform(0.02, 0.2), 50), B1: sp.Float(rng.uniform(0.5, 2), 50),
                 B2: sp.Float(rng.uniform(0.5, 2), 50), C1: sp.Float(rng.uniform(0.5, 2), 50),
                 C2: sp.Float(rng.uniform(0.5, 2), 50), w01: sp.Float(rng.uniform(-1, 1), 50),
                 w02: sp.Float(rng.uniform(-1, 1), 50)}
        vals.update(mvals)
        rhs_v = [sp.N(e.subs(vals), 50) for e in RHS]
        for name, gr in grads.items():
            terms = [sp.N(gr[j].subs(vals), 50) * rhs_v[j] for j in range(NDIM)]
            tot = abs(sum(terms))
            scale = sum(abs(t) for t in terms) + 1
            worst[name] = max(worst[name], float(tot / scale))
    for name in worst:
        check("d/ds %s = 0 at 5 random points (relative residual %.1e < 1e-40)"
              % (name, worst[name]), worst[name] < 1e-40)


def random_points(n, seed):
    """n random non-singular points (state + material) as 50-digit Floats."""
    rng = random.Random(seed)
    pts = []
    for _ in range(n):
        vals = {x: sp.Float(rng.uniform(-1.0, 1.0), 50) for x in U}
        vals[eta] = sp.Float(rng.uniform(-0.6, 0.6), 50)
        vals[w3] = sp.Float(rng.uniform(-2.0, 3.0), 50)
        vals.update({Delta: sp.Float(rng.uniform(0.02, 0.2), 50),
                     B1: sp.Float(rng.uniform(0.5, 2), 50), B2: sp.Float(rng.uniform(0.5, 2), 50),
                     C1: sp.Float(rng.uniform(0.5, 2), 50), C2: sp.Float(rng.uniform(0.5, 2), 50),
                     w01: sp.Float(rng.uniform(-1, 1), 50), w02: sp.Float(rng.uniform(-1, 1), 50)})
        pts.append(vals)
    return pts


def check_closed_forms():
    """The closed forms written in doc/braid-equations.md (D3, D5, D6, D8)
    against the expressions the C code is generated from, at random points in
    50-digit arithmetic (relative difference < 1e-40)."""
    Y = omd
    A = M2 - B1 * w2
    h_doc = (ce / Delta * (B1 * w3 - M3) - se / Delta * (M1 + T1) + A**2 / (2 * B2)
             + (T2**2 + 2 * C2 * w02 * T2) / (2 * C2) + B2 / (2 * Delta**2) * (ce**4 / Y**2 - 1))
    dgdeta_doc = (-se * Y * A**2 / (2 * B2 * ce**2)
                  - B2 * se * (ce**2 - Y) * (3 * ce**2 + Y) / (2 * Delta**2 * Y * ce**2)
                  + T1 * Y / (Delta * ce**2) - se * Y * (T2**2 + 2 * C2 * w02 * T2) / (2 * C2 * ce**2)
                  - ce * T2 / Delta + h_s * Y * se / ce**2)
    Mp2, Mp1, Mp3 = Mp[1], Mp[0], Mp[2]
    w2p_doc = (Mp2 - dgdeta_doc.subs(h_s, h_doc) - M1 * Y / (Delta * ce**2)) / B1
    w3p_doc = ((te * Mp1 + Mp3 - Delta * A * (Mp2 - B1 * w2p_doc) / (B2 * ce)
                + (te * (B1 * w3 - M3) + M1 + T1 + 2 * B2 * se * ce**2 / (Delta * Y**2)) * etap)
               / (B1 + B2 * ce**3 / Y**3))
    sig = sigmap
    ham_doc = ((M1 + T1) * w1 + M3 * w3 + B1 * (w2**2 - w3**2) / 2 + sig * A**2 / (2 * B2)
               + T1**2 / (2 * C1) - T1 * w01 + T2 * se / Delta + sig * (T2**2 / (2 * C2) + T2 * w02)
               - B2 * (w3 - se**2 / Delta)**2 / (2 * Y * ce) - h_doc * sig + F1)
    g_e_doc = (B1 * (w2**2 + w3**2) / 2 + sig * A**2 / (2 * B2)
               + B2 * (w3 - se**2 / Delta)**2 / (2 * Y * ce) + T1**2 / (2 * C1) + sig * T2**2 / (2 * C2))
    pairs = [("h (D3)", h_doc, h_expr),
             ("dg/deta at the state (D5)", dgdeta_doc, sp.diff(g, eta).subs(SUB)),
             ("omega2' (D5)", w2p_doc, w2p),
             ("omega3' (D6)", w3p_doc, w3p),
             ("g_e at the state (D8)", g_e_doc, g_e.subs(SUB)),
             ("Hamiltonian (D8)", ham_doc, ham)]
    pts = random_points(4, 777)
    for name, a, b in pairs:
        worst = 0.0
        for vals in pts:
            va = sp.N(a.subs(h_s, 0.375).subs(vals), 50)
            vb = sp.N(b.subs(h_s, 0.375).subs(vals), 50)
            worst = max(worst, float(abs(va - vb) / (abs(vb) + 1)))
        check("closed form of %s (relative difference %.1e < 1e-40)" % (name, worst), worst < 1e-40)


def check_pressure_identities():
    check("(Delta d1 x n2) has no d1 component: M2 = m1.d1 + m2.d1",
          sp.simplify(Kv[1]) == 0)


# ---------------------------------------------------------------------------
# C emission
# ---------------------------------------------------------------------------
class BraidPrinter(C99CodePrinter):
    """C99 printer: small integer powers as products, no pow() for them."""

    def _print_Pow(self, expr):
        b, e = expr.base, expr.exp
        if e.is_Integer and 1 <= abs(int(e)) <= 4:
            base = self.parenthesize(b, 100)
            prod = "*".join([base] * abs(int(e)))
            # parenthesised: the Mul printer treats a Pow as one factor ("a/b**2")
            return "(%s)" % prod if int(e) > 0 else "(1.0/(%s))" % prod
        if e == sp.Rational(1, 2):
            return "sqrt(%s)" % self._print(b)
        return super()._print_Pow(expr)


PRINTER = BraidPrinter()


def ccode(e):
    return PRINTER.doprint(e)


def to_sincos(e):
    e = sp.sympify(e)
    assert not e.has(sp.tan), "tan(eta) is written as sin/cos throughout"
    return e


def emit_function(signature, comment, outputs, inputs, zero_fill=None):
    """outputs: list of (lvalue, expr).  inputs: list of (symbol, cexpr) unpacked
    on demand.  zero_fill: list of (array, n) set to zero before the stores."""
    exprs = [to_sincos(e) for _, e in outputs]
    repl, red = sp.cse(exprs, symbols=sp.numbered_symbols("k"), optimizations="basic")
    used = set()
    for _, e in repl:
        used |= e.free_symbols
    for e in red:
        used |= e.free_symbols
    lines = ["/* %s */" % comment, signature, "{"]
    for sym, cexpr in inputs:
        if sym in used:
            lines.append("  const double %s = %s;" % (sym.name, cexpr))
    for sym, e in repl:
        lines.append("  const double %s = %s;" % (sym.name, ccode(e)))
    if zero_fill:
        for arr, n in zero_fill:
            lines.append("  for (int i = 0; i < %d; i++) %s[i] = 0.0;" % (n, arr))
    zeroed = {arr for arr, _ in (zero_fill or [])}
    for (lv, _), e in zip(outputs, red):
        # a zero entry may be skipped only in an array that was zero-filled above
        if e == 0 and lv.split("[")[0] in zeroed:
            continue
        lines.append("  %s = %s;" % (lv, ccode(e)))
    lines.append("}")
    return "\n".join(lines) + "\n"


def state_inputs(arr="u"):
    return [(U[k], "%s[%d]" % (arr, k)) for k in range(NDIM)]


def mat_inputs(arr="p"):
    return [(P[k], "%s[%d]" % (arr, k)) for k in range(NMAT)]


def generate():
    funcs = []
    # rhs only
    funcs.append(emit_function(
        "void braid_gen_rhs(const double *u, const double *p, double *f)",
        "d/ds of the 21 states.",
        [("f[%d]" % i, RHS[i]) for i in range(NDIM)],
        state_inputs() + mat_inputs()))
    # rhs + Jacobians
    outs = [("f[%d]" % i, RHS[i]) for i in range(NDIM)]
    for j in range(NDIM):
        for i in range(NDIM):
            d = sp.diff(RHS[i], U[j])
            if d != 0:
                outs.append(("ju[%d]" % (i + NDIM * j), d))
    for j in range(NMAT):
        for i in range(NDIM):
            d = sp.diff(RHS[i], P[j])
            if d != 0:
                outs.append(("jm[%d]" % (i + NDIM * j), d))
    funcs.append(emit_function(
        "void braid_gen_rhs_jac(const double *u, const double *p, double *f, double *ju, double *jm)",
        "d/ds of the 21 states, ju = d f/d u (21x21), jm = d f/d (Delta,B1,B2,C1,C2,w01,w02)"
        " (21x7), column-major.",
        outs, state_inputs() + mat_inputs(),
        zero_fill=[("ju", NDIM * NDIM), ("jm", NDIM * NMAT)]))
    funcs.append(emit_function(
        "void braid_gen_aux(const double *u, const double *p, double *aux)",
        "aux = (omega1, sigma', eta', xi1', xi2', h, d h/d omega3).",
        [("aux[%d]" % i, AUX[i]) for i in range(len(AUX))],
        state_inputs() + mat_inputs()))
    funcs.append(emit_function(
        "void braid_gen_integrals(const double *u, const double *p, double *out)",
        "out = (|F|^2, F.M, h, |q|^2, T1, T2, Hamiltonian).",
        [("out[%d]" % i, INTEGRALS[i]) for i in range(len(INTEGRALS))],
        state_inputs() + mat_inputs()))
    funcs.append(emit_function(
        "void braid_gen_gpartials(const double *x, const double *p, double *out)",
        "x = (eta, eta', omega2, omega3, xi1', xi2', h); out = (g + F1, dg/domega2, dg/domega3,"
        " dg/deta, dg/deta', dg/dxi1', dg/dxi2').",
        [("out[%d]" % i, GPARTIALS[i]) for i in range(len(GPARTIALS))],
        [(GP_ARGS[k], "x[%d]" % k) for k in range(len(GP_ARGS))] + mat_inputs()))
    funcs.append(emit_function(
        "void braid_gen_pressure(const double *u, const double *up, const double *upp,"
        " const double *p, double *out)",
        "up = u', upp = u''; out = (p from strand 1, p from strand 2, n1 (t1,d1,u1), n2 (t1,d1,u1),"
        " t1 and u1 parts of n2', sigma').",
        [("out[%d]" % i, PRESSURE[i]) for i in range(len(PRESSURE))],
        state_inputs() + [(UP[k], "up[%d]" % k) for k in range(NDIM)]
        + [(UPP[k], "upp[%d]" % k) for k in range(NDIM)] + mat_inputs()))

    header_c = (
        "/* GENERATED by scripts/gen_braid.py -- do not edit.\n"
        " * Regenerate from the repository root with\n"
        " *     /usr/bin/python3 scripts/gen_braid.py\n"
        " * (sympy %s).  The derivation is in doc/braid-equations.md.\n"
        " * u: the 21 states (equations/braid_state.h); p: (Delta, B1, B2, C1, C2, w01, w02).\n"
        " * No guard against singular configurations here: braid_model.c checks\n"
        " * cos(eta) and 1 - Delta*omega3 before calling. */\n" % sp.__version__)
    src = header_c + "#include <math.h>\n\n#include \"braid_rhs_gen.h\"\n\n" + "\n".join(funcs)
    hdr = (
        "/* GENERATED by scripts/gen_braid.py -- do not edit.  Private to equations/:\n"
        " * the entry points of the generated code; braid_model.c, braid_integrals.c\n"
        " * and braid_pressure.c wrap them with guards. */\n"
        "#ifndef CABLE_BRAID_RHS_GEN_H\n#define CABLE_BRAID_RHS_GEN_H\n\n"
        "#define BRAID_GEN_NAUX %d\n#define BRAID_GEN_NINT %d\n#define BRAID_GEN_NGP %d\n"
        "#define BRAID_GEN_NPRES %d\n\n" % (len(AUX), len(INTEGRALS), len(GPARTIALS), len(PRESSURE)))
    for f in funcs:
        sig_line = f.split("\n")[1]
        hdr += sig_line + ";\n"
    hdr += "\n#endif\n"
    # The AUTO-07p equation file: the same generated right-hand side (static),
    # then the hand-written FUNC/BCND/PVLS of scripts/auto_braid_knot.c.in.
    with open(os.path.join(ROOT, "scripts", "auto_braid_knot.c.in")) as fh:
        template = fh.read()
    auto = (
        "/* GENERATED by scripts/gen_braid.py -- do not edit.  The flat braid knot as an\n"
        " * AUTO-07p equation file (AUTO's C interface): the right-hand side and its\n"
        " * Jacobians are the same generated code as cable's equations/braid_rhs_gen.c\n"
        " * (sympy %s); doc/benchmarks.md runs it in AUTO-07p and in cable. */\n"
        "#include <math.h>\n\n" % sp.__version__)
    for k in (0, 1, 3):
        auto += funcs[k].replace("\nvoid braid_gen_", "\nstatic void braid_gen_", 1) + "\n"
    auto += template
    return src, hdr, auto


def main():
    check_g_lines()
    check_eta_chain_rule()
    check_inversions()
    check_quaternions()
    check_pressure_identities()
    check_closed_forms()
    check_integrals_numeric()
    if "--check" in sys.argv:
        return
    src, hdr, auto = generate()
    with open(os.path.join(ROOT, "equations", "braid_rhs_gen.c"), "w") as fh:
        fh.write(src)
    with open(os.path.join(ROOT, "equations", "braid_rhs_gen.h"), "w") as fh:
        fh.write(hdr)
    with open(os.path.join(ROOT, "tests", "auto07p", "knot72auto.c"), "w") as fh:
        fh.write(auto)
    print("wrote equations/braid_rhs_gen.c (%d lines), equations/braid_rhs_gen.h, "
          "tests/auto07p/knot72auto.c" % src.count("\n"))


if __name__ == "__main__":
    main()
