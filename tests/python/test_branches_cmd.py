# SPDX-License-Identifier: GPL-3.0-or-later
"""branches(bp): the branch directions at a double branch point (doc/engine.md,
"Multiple branch points"), as an AUTO user's equation file gets them.

Two uncoupled elasticas theta_i'' + lambda sin(theta_i) = 0, theta_i'(0) =
theta_i'(1) = 0 (an AUTO .f90 file: no symmetry can be declared there): the
trivial branch's first branch point lambda = pi^2 is double, and its four
branches are known exactly, theta1 alone, theta1 = theta2, theta2 alone,
theta1 = -theta2: phi = 0, 45, 90, 135 degrees from e1 (only theta1 moves),
each with lambda = pi^2 + mu s^2 at second order, mu = pi^2 c^2 / 8 for one
buckled rod and pi^2 c^2 / 16 for both (c^2 = 2 / (1 + pi^2), the unit
kernel vector's amplitude; tests/test_branches.c derives them).  Tolerances
as there: phi to 1e-3 degrees, mu to 1e-4 relative (third differences of
the residual, doc/engine.md).  Then run(bp, ISW=-1, BRANCH=2) follows the
in-phase branch theta1 = theta2."""
import math

import pytest

import cable

PAIR_F90 = """! two uncoupled elasticas: U = (theta1, theta1', theta2, theta2')
SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
  INTEGER NDIM, ICP(*), IJAC
  DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,*), DFDP(NDIM,*)
  F(1) = U(2)
  F(2) = -PAR(1) * SIN(U(1))
  F(3) = U(4)
  F(4) = -PAR(1) * SIN(U(3))
END SUBROUTINE FUNC
SUBROUTINE STPNT(NDIM,U,PAR,T)
  INTEGER NDIM
  DOUBLE PRECISION U(NDIM), PAR(*), T
  PAR(1) = 1.0D0
  U(1) = 0.0D0
  U(2) = 0.0D0
  U(3) = 0.0D0
  U(4) = 0.0D0
END SUBROUTINE STPNT
SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
  INTEGER NDIM, ICP(*), NBC, IJAC
  DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
  FB(1) = U0(2)
  FB(2) = U1(2)
  FB(3) = U0(4)
  FB(4) = U1(4)
END SUBROUTINE BCND
SUBROUTINE ICND
END SUBROUTINE ICND
SUBROUTINE FOPT
END SUBROUTINE FOPT
SUBROUTINE PVLS
END SUBROUTINE PVLS
"""


def test_branches_of_two_elasticas(work, monkeypatch):
    monkeypatch.setenv('CABLE_CACHE_DIR', str(work / 'cache'))
    with open('pair.f90', 'w') as f:
        f.write(PAIR_F90)
    with open('c.pair', 'w') as f:
        f.write("NDIM=4, IPS=4, NBC=4, NINT=0, ICP=[1], NTST=40, NCOL=4, JAC=0, IAD=0\n"
                "ISP=2, ILP=0, DS=0.5, DSMIN=1e-6, DSMAX=3.0, NMX=100, RL1=12.0, EPSS=1e-9\n")
    r = cable.Runner()
    triv = r.run(e='pair', c='pair')
    bp = triv('BP1')
    assert bp['PAR(1)'] == pytest.approx(math.pi ** 2, rel=1e-7)
    before = r.session.constants()
    dirs = r.branches(bp, DS=0.05, DSMAX=0.2, ISP=0)
    # a probe: the runner's constants stay those of the last run
    after = r.session.constants()
    assert after == before and after['NMX'] == 100 and after['ISW'] == 1, after
    assert r.last is triv
    c2, pi2 = 2.0 / (1.0 + math.pi ** 2), math.pi ** 2
    want = [(0.0, pi2 * c2 / 8), (45.0, pi2 * c2 / 16), (90.0, pi2 * c2 / 8), (135.0, pi2 * c2 / 16)]
    assert [d['BRANCH'] for d in dirs] == [1, 2, 3, 4]
    for d, (phi, mu) in zip(dirs, want):
        assert d['order'] == 3
        assert abs(d['phi'] - phi) < 1e-3, d
        assert d['mu'] == pytest.approx(mu, rel=1e-4), d
        assert d['multiplicity'] == 1 and not d['symmetric'] and not d['restricted']
        assert abs(math.hypot(d['a'][1], d['a'][2]) - 1.0) < 1e-12 and d['a'][0] == 0.0
    # the listed BRANCH=2 is the in-phase branch
    br = r.run(bp, e='pair', c='pair', ISW=-1, BRANCH=2, DS=0.05, DSMAX=0.2, ISP=0, NMX=25, NPR=5)
    sols = br()[1:]
    assert sols
    for s in sols:
        u = s.coordarray
        assert max(abs(u[0] - u[2])) < 1e-6 and max(abs(u[0])) > 0.05
    # a simple or no branch point has no list
    with pytest.raises(cable.CableError, match='branch point'):
        r.branches(triv('EP1'), DS=0.05)
